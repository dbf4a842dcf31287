// SPDX-License-Identifier: MIT
#include "TetrahedraRemover.h"
#include "TopologicalChangeProcessor.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("TetrahedraRemover",
           "Removes tetrahedra while the simulation runs: listed per time, in boxes, or swept by "
           "a moving tool segment")
      .with<TetrahedraRemover>();
  registry
      .add("TopologicalChangeProcessor",
           "Applies the topological changes of a SOFA change file (REMOVE= of tetrahedra or "
           "of a surface's triangles) at their times")
      .with<TopologicalChangeProcessor>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Cutting", "0.1.0", "Cutting: removing tetrahedra at run time", registerComponents);
  return &entry;
}
