// SPDX-License-Identifier: MIT
#include "ConstantForceField.h"
#include "Gravity.h"
#include "PlaneForceField.h"
#include "TrianglePressureForceField.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("ConstantForceField", "Constant forces on points or rigid frames")
      .with<ConstantForceField<Vec3Types>>("Vec3d")
      .with<ConstantForceField<Vec2Types>>("Vec2d")
      .with<ConstantForceField<Vec1Types>>("Vec1d")
      .with<ConstantForceField<Rigid3Types>>("Rigid3d");
  registry.add("Gravity", "Sets the gravity of its node and the nodes below").with<Gravity>();
  registry.add("PlaneForceField", "Penalty plane pushing points back to its free side")
      .with<PlaneForceField<Vec3Types>>("Vec3d")
      .with<PlaneForceField<Rigid3Types>>("Rigid3d");
  registry.add("TrianglePressureForceField", "A pressure (force per unit area) on triangles")
      .with<TrianglePressureForceField>("Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("MechanicalLoad", "0.1.0", "External loads", registerComponents);
  return &entry;
}
