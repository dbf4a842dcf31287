// SPDX-License-Identifier: MIT
#include "CGLinearSolver.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("CGLinearSolver", "Conjugate gradient, matrix-free or on the assembled matrix")
      .with<CGLinearSolver>("GraphScattered")
      .with<CGLinearSolver>("CompressedRowSparseMatrixMat3x3d")
      .with<CGLinearSolver>("CompressedRowSparseMatrixd");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("LinearSolver", "0.1.0", "Linear solvers", registerComponents);
  return &entry;
}
