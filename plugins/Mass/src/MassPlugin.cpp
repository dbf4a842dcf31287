// SPDX-License-Identifier: MIT
#include "DiagonalMass.h"
#include "MeshMatrixMass.h"
#include "UniformMass.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("UniformMass", "The same mass at every point or rigid frame; applies gravity")
      .with<UniformMass<Vec3Types>>("Vec3d")
      .with<UniformMass<Vec2Types>>("Vec2d")
      .with<UniformMass<Vec1Types>>("Vec1d")
      .with<UniformMass<Rigid3Types>>("Rigid3d");
  // SOFA scenes also write the mass templates as "Vec3,Vec3" (state and geometry types).
  registry.add("DiagonalMass", "Lumped mass from the volumes of the topology's elements")
      .with<DiagonalMass>("Vec3d")
      .with<DiagonalMass>("Vec3d,Vec3d");
  registry
      .add("MeshMatrixMass", "Consistent (or lumped) mass matrix of the topology's linear elements")
      .with<MeshMatrixMass>("Vec3d")
      .with<MeshMatrixMass>("Vec3d,Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("Mass", "0.1.0", "Masses (with gravity)", registerComponents);
  return &entry;
}
