// SPDX-License-Identifier: MIT
#include "TetrahedralTensorMassForceField.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("TetrahedralTensorMassForceField",
           "Linear elasticity on tetrahedra, tensors stored on vertices and edges")
      .with<TetrahedralTensorMassForceField>("Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "TensorMass", "0.1.0", "Tensor-mass models of soft tissue on tetrahedra", registerComponents);
  return &entry;
}
