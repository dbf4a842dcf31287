// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "core/DataTraits.h"
#include "linalg/AssembledMatrix.h"
#include "simulation/Solvers.h"

struct cholmod_common_struct;
struct cholmod_factor_struct;
struct cholmod_dense_struct;

namespace stroma {

/// How CHOLMOD stores and computes L: it chooses by the operation count (auto), or always
/// supernodal (dense blocks through BLAS, best for large 3D meshes), or always simplicial
/// (column by column, best for small or very sparse systems).
enum class CholmodFactorization { automatic, supernodal, simplicial };
template <>
struct EnumKeywords<CholmodFactorization> {
  static constexpr std::array<std::string_view, 3> names{"auto", "supernodal", "simplicial"};
};

/// The fill-reducing ordering, with the keywords of SOFA's SparseCholeskySolver: None (the
/// system's order), SuiteSparse (AMD, Amestoy, Davis and Duff 1996) or METIS (nested
/// dissection, Karypis and Kumar 1998).
enum class CholmodPermutation { none, suiteSparse, metis };
template <>
struct EnumKeywords<CholmodPermutation> {
  static constexpr std::array<std::string_view, 3> names{"None", "SuiteSparse", "METIS"};
};

/// Direct sparse Cholesky A = L L^T by CHOLMOD (Chen, Davis, Hager and Rajamanickam 2008,
/// "Algorithm 887: CHOLMOD, supernodal sparse Cholesky factorization and update/downdate",
/// ACM TOMS 35(3)); also answers to SOFA's SparseCholeskySolver. A = m M + b B + k K is
/// assembled at every solve (fixed degrees of freedom as identity rows). The symbolic analysis
/// (ordering, elimination tree, supernodes) is redone only when the sparsity pattern changed
/// (AssembledMatrix::patternRevision()); each solve refactorizes numerically into the same
/// factor, and the triangular solves reuse their workspace (no allocation per step).
///
/// The system of a mechanical step is symmetric positive definite: a failed factorization
/// (not positive definite, or not finite) is reported as an error naming the degree of freedom
/// of the failing column, and the solve returns zero.
class CholmodSolver final : public LinearSolver {
 public:
  Data<CholmodFactorization> d_factorization{
      this, "factorization", CholmodFactorization::automatic,
      "Supernodal or simplicial LL^T; auto lets CHOLMOD choose by operation count."};
  Data<CholmodPermutation> d_permutation{this, "permutation", CholmodPermutation::suiteSparse,
                                         "Fill-reducing ordering (read when the pattern is "
                                         "analyzed)."};
  Data<int> d_symbolicAnalyses{this,
                               "symbolicAnalyses",
                               0,
                               "Symbolic analyses so far (one per sparsity pattern).",
                               {.output = true}};
  Data<int> d_factorizations{
      this, "factorizations", 0, "Numeric factorizations so far.", {.output = true}};
  Data<double> d_LNnz{
      this, "L_nnz", 0.0, "Non-zeros of the factor L (from the analysis).", {.output = true}};
  Data<bool> d_supernodalFactor{
      this, "supernodalFactor", false, "Whether the last factor is supernodal.", {.output = true}};

  CholmodSolver();
  ~CholmodSolver() override;

  LinearSolveReport solve(MechanicalOperations& mop, const MechanicalParams& mp, VecId x,
                          VecId rhs) override;

 private:
  bool analyze();

  AssembledMatrix m_matrix;
  cholmod_common_struct* m_common = nullptr;
  cholmod_factor_struct* m_factor = nullptr;
  cholmod_dense_struct* m_x = nullptr;  ///< solve2 workspaces, reused
  cholmod_dense_struct* m_y = nullptr;
  cholmod_dense_struct* m_e = nullptr;
  std::uint64_t m_analyzedRevision = 0;  ///< patternRevision() of the analysis; 0: none
  Eigen::VectorXd m_rhs, m_solution;
};

}  // namespace stroma
