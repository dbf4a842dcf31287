// SPDX-License-Identifier: MIT
#include "MechanicalObject.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("MechanicalObject", "Positions, velocities and forces of a set of points or frames")
      .with<MechanicalObject<Vec3Types>>("Vec3d")
      .with<MechanicalObject<Vec2Types>>("Vec2d")
      .with<MechanicalObject<Vec1Types>>("Vec1d")
      .with<MechanicalObject<Rigid3Types>>("Rigid3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "StateContainer", "0.1.0", "Mechanical states (degrees of freedom)", registerComponents);
  return &entry;
}
