// SPDX-License-Identifier: MIT
#include "FastTriangularBendingSprings.h"
#include "MeshSpringForceField.h"
#include "QuadBendingSprings.h"
#include "QuadularBendingSprings.h"
#include "RegularGridSpringForceField.h"
#include "SpringForceField.h"
#include "TriangularBendingSprings.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("SpringForceField", "Linear springs between points of one or two states")
      .with<SpringForceField<Vec3Types>>("Vec3d")
      .with<SpringForceField<Vec2Types>>("Vec2d")
      .with<SpringForceField<Vec1Types>>("Vec1d")
      .alias("StiffSpringForceField");
  registry.add("MeshSpringForceField", "Linear springs along the edges of a mesh's elements")
      .with<MeshSpringForceField<Vec3Types>>("Vec3d")
      .with<MeshSpringForceField<Vec2Types>>("Vec2d")
      .with<MeshSpringForceField<Vec1Types>>("Vec1d");
  registry
      .add("TriangularBendingSprings",
           "Springs between the vertices opposite each edge shared by two triangles")
      .with<TriangularBendingSprings<Vec3Types>>("Vec3d")
      .with<TriangularBendingSprings<Vec2Types>>("Vec2d");
  registry
      .add("FastTriangularBendingSprings",
           "Linear bending energy of each pair of triangles sharing an edge")
      .with<FastTriangularBendingSprings>("Vec3d");
  registry.add("QuadularBendingSprings", "Springs across each edge shared by two quads, per edge")
      .with<QuadularBendingSprings<Vec3Types>>("Vec3d")
      .with<QuadularBendingSprings<Vec2Types>>("Vec2d");
  registry.add("QuadBendingSprings", "Springs across the edges shared by two quads, each once")
      .with<QuadBendingSprings<Vec3Types>>("Vec3d")
      .with<QuadBendingSprings<Vec2Types>>("Vec2d");
  registry
      .add("RegularGridSpringForceField",
           "Springs along the lines, face diagonals and cell diagonals of a grid")
      .with<RegularGridSpringForceField<Vec3Types>>("Vec3d")
      .with<RegularGridSpringForceField<Vec2Types>>("Vec2d")
      .with<RegularGridSpringForceField<Vec1Types>>("Vec1d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("Spring", "0.1.0", "Mass-spring models", registerComponents);
  return &entry;
}
