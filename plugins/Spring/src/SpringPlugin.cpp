// SPDX-License-Identifier: MIT
#include "MeshSpringForceField.h"
#include "SpringForceField.h"
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
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("Spring", "0.1.0", "Mass-spring models", registerComponents);
  return &entry;
}
