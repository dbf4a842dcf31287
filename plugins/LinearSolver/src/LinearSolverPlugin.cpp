// SPDX-License-Identifier: MIT
#include "CGLinearSolver.h"
#include "PCGLinearSolver.h"
#include "SparseLDLSolver.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  // SOFA scenes also write the assembled templates without their precision suffix
  // ("CompressedRowSparseMatrixMat3x3"), which means double there as here.
  registry.add("CGLinearSolver", "Conjugate gradient, matrix-free or on the assembled matrix")
      .with<CGLinearSolver>("GraphScattered")
      .with<CGLinearSolver>("CompressedRowSparseMatrixMat3x3d")
      .with<CGLinearSolver>("CompressedRowSparseMatrixd")
      .with<CGLinearSolver>("CompressedRowSparseMatrixMat3x3")
      .with<CGLinearSolver>("CompressedRowSparseMatrix");
  registry.add("PCGLinearSolver",
               "Matrix-free conjugate gradient preconditioned by another linear solver")
      .with<PCGLinearSolver>("GraphScattered");
  // AsyncSparseLDLSolver is SOFA's SparseLDLSolver whose factorization runs in a thread, a step
  // late: the same model and system. Stroma factorizes synchronously (README: more accurate).
  registry.add("SparseLDLSolver", "Direct sparse LDL^T solver (Eigen SimplicialLDLT)")
      .with<SparseLDLSolver>("CompressedRowSparseMatrixd")
      .with<SparseLDLSolver>("CompressedRowSparseMatrixMat3x3d")
      .with<SparseLDLSolver>("CompressedRowSparseMatrix")
      .with<SparseLDLSolver>("CompressedRowSparseMatrixMat3x3")
      .alias("AsyncSparseLDLSolver")
      .alias("EigenSimplicialLDLT")
      .alias("EigenSimplicialLLT");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("LinearSolver", "0.1.0", "Linear solvers", registerComponents);
  return &entry;
}
