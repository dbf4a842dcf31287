// SPDX-License-Identifier: MIT
#include "PrecomputedLinearModel.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("PrecomputedLinearModel",
           "Quasi-static linear elasticity by a precomputed deformation basis (Cotin 1999): "
           "displacements from forces and imposed displacements on the surface by superposition")
      .with<PrecomputedLinearModel>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Precomputed", "0.1.0",
      "The precomputed quasi-static linear model of Cotin, Delingette and Ayache (1999)",
      registerComponents);
  return &entry;
}
