// SPDX-License-Identifier: MIT
#include "MultiresolutionGridTopology.h"
#include "TNodeConstraint.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("MultiresolutionGridTopology",
           "Hexahedra of a box grid with cells refined 2 x 2 x 2 in given boxes, and its T-nodes")
      .with<MultiresolutionGridTopology>();
  registry
      .add("TNodeConstraint",
           "Keeps the T-nodes of a multiresolution grid interpolated from their parents "
           "(forces pushed to the parents, CG as Nesme's Algorithm 1)")
      .with<TNodeConstraint>("Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Multiresolution", "0.1.0",
      "Hexahedral grids mixing two resolutions, with T-nodes (Nesme 2008)", registerComponents);
  return &entry;
}
