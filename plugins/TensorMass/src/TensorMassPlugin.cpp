// SPDX-License-Identifier: MIT
#include "StandardTetrahedralFEMForceField.h"
#include "TetrahedralStVKTensorMassForceField.h"
#include "TetrahedralTensorMassForceField.h"
#include "TetrahedralVolumePenaltyForceField.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("TetrahedralTensorMassForceField",
           "Linear elasticity on tetrahedra, tensors stored on vertices and edges")
      .with<TetrahedralTensorMassForceField>("Vec3d");
  registry
      .add("TetrahedralStVKTensorMassForceField",
           "St Venant-Kirchhoff elasticity on tetrahedra, tensor-mass form (Picinbono, Delingette, "
           "Ayache)")
      .with<TetrahedralStVKTensorMassForceField>("Vec3d");
  registry
      .add("StandardTetrahedralFEMForceField",
           "Hyperelastic tetrahedra element by element (St Venant-Kirchhoff, neo-Hookean)")
      .with<StandardTetrahedralFEMForceField>("Vec3d");
  registry
      .add("TetrahedralVolumePenaltyForceField",
           "Incompressibility penalty on the volume of each tetrahedron (Picinbono, Delingette, "
           "Ayache)")
      .with<TetrahedralVolumePenaltyForceField>("Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "TensorMass", "0.1.0",
      "Tensor-mass models (linear, St Venant-Kirchhoff), hyperelastic tetrahedra, volume penalty",
      registerComponents);
  return &entry;
}
