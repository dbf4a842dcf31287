// SPDX-License-Identifier: MIT
#include "SparseGridTopology.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("SparseGridTopology",
           "The hexahedra of a regular grid around a triangle surface, empty cells dropped, "
           "with each cell's type and filled volume fraction")
      .with<SparseGridTopology>()
      .alias("SparseGrid");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "SparseGrid", "0.1.0", "Sparse hexahedral grids built around surfaces (Nesme 2008)",
      registerComponents);
  return &entry;
}
