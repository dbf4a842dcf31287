// SPDX-License-Identifier: MIT
#include "FixedProjectiveConstraint.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("FixedProjectiveConstraint", "Fixes points by projection")
      .with<FixedProjectiveConstraint>("Vec3d")
      .alias("FixedConstraint");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Constraint", "0.1.0", "Projective constraints", registerComponents);
  return &entry;
}
