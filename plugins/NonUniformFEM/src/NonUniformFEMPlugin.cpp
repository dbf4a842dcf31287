// SPDX-License-Identifier: MIT
#include "NonUniformHexahedronFEMForceFieldAndMass.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("NonUniformHexahedronFEMForceFieldAndMass",
           "Corotational hexahedra of a sparse grid, stiffness and mass condensed from its finer "
           "levels (filled fractions, per-voxel material)")
      .with<NonUniformHexahedronFEMForceFieldAndMass>("Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "NonUniformFEM", "0.1.0",
      "Non-uniform hexahedra condensed from nested sparse-grid levels (Nesme 2008, ch. 4.3)",
      registerComponents);
  return &entry;
}
