// SPDX-License-Identifier: MIT
#include "TetrahedralFiberReinforcementForceField.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("TetrahedralFiberReinforcementForceField",
           "Fiber reinforcement on tetrahedra: the anisotropic part of transversely isotropic "
           "linear elasticity (Spencer), beside an isotropic force field")
      .with<TetrahedralFiberReinforcementForceField>("Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Anisotropy", "0.1.0",
      "Anisotropic elasticity: fiber reinforcement of tetrahedra (transversely isotropic)",
      registerComponents);
  return &entry;
}
