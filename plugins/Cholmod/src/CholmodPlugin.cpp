// SPDX-License-Identifier: MIT
#include "CholmodSolver.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  // SOFA's SparseCholeskySolver is the same model (sparse LL^T with a fill-reducing ordering,
  // through CSparse there); its scenes run unmodified on CHOLMOD.
  registry.add("CholmodSolver", "Direct sparse Cholesky LL^T solver (SuiteSparse CHOLMOD)")
      .with<CholmodSolver>("CompressedRowSparseMatrixd")
      .with<CholmodSolver>("CompressedRowSparseMatrixMat3x3d")
      .with<CholmodSolver>("CompressedRowSparseMatrix")
      .with<CholmodSolver>("CompressedRowSparseMatrixMat3x3")
      .alias("SparseCholeskySolver");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Cholmod", "0.1.0", "Direct sparse Cholesky by SuiteSparse CHOLMOD", registerComponents);
  return &entry;
}
