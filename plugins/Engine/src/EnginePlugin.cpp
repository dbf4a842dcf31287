// SPDX-License-Identifier: MIT
#include "BoxROI.h"
#include "GenerateRigidMass.h"
#include "SphereROI.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("BoxROI", "Selects the points and elements inside boxes (a data engine)")
      .with<BoxROI<Vec3Types>>("Vec3d")
      .with<BoxROI<Vec2Types>>("Vec2d")
      .with<BoxROI<Vec1Types>>("Vec1d")
      // SOFA's PlaneROI selects what lies in the parallelogram p0, p1, p2, p0 + p2 - p1 extruded
      // by depth/2 on each side, all points of an element inside: BoxROI's orientedBox, which
      // also reads PlaneROI's attribute name `plane`.
      .alias("PlaneROI");
  registry.add("SphereROI", "Selects the points and elements inside spheres (a data engine)")
      .with<SphereROI>("Vec3d");
  registry
      .add(
          "GenerateRigidMass",
          "Mass, center and inertia of a homogeneous solid from its closed surface (a data engine)")
      .with<GenerateRigidMass>("Rigid3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Engine", "0.1.0", "Data engines: regions of interest, rigid masses of closed surfaces",
      registerComponents);
  return &entry;
}
