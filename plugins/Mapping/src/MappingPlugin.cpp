// SPDX-License-Identifier: MIT
#include "BarycentricMapping.h"
#include "IdentityMapping.h"
#include "RigidMapping.h"
#include "SubsetMapping.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("IdentityMapping", "The output is a copy of the input")
      .with<IdentityMapping<Vec3Types>>("Vec3d,Vec3d")
      .with<IdentityMapping<Rigid3Types>>("Rigid3d,Rigid3d");
  registry.add("SubsetMapping", "The output is a subset of the input's points")
      .with<SubsetMapping>("Vec3d,Vec3d");
  registry.add("RigidMapping", "Points attached to rigid frames")
      .with<RigidMapping>("Rigid3d,Vec3d");
  registry.add("BarycentricMapping", "Points embedded in the tetrahedra or hexahedra of a mesh")
      .with<BarycentricMapping>("Vec3d,Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Mapping", "0.1.0", "Mappings between states (identity, subset, rigid, barycentric)",
      registerComponents);
  return &entry;
}
