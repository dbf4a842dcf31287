// SPDX-License-Identifier: MIT
#include "EmbeddedPointConstraint.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("EmbeddedPointConstraint",
           "Fixes or moves points of an embedded surface by constraining the grid through the "
           "pseudo-inverse of the interpolation")
      .with<EmbeddedPointConstraint>("Vec3d")
      .alias("EmbeddedFixedConstraint");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Embedding", "0.1.0",
      "Constraints on surfaces embedded in a grid, through the interpolation (Nesme 2008)",
      registerComponents);
  return &entry;
}
