// SPDX-License-Identifier: MIT
#include "MultigridLinearSolver.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("MultigridLinearSolver",
           "Geometric multigrid on nested hexahedral grids, CG smoother (V or full cycle)")
      .with<MultigridLinearSolver>()
      .alias("MultiGridSolver");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Multigrid", "0.1.0", "Geometric multigrid linear solver", registerComponents);
  return &entry;
}
