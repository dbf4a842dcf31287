// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/SparseCholesky>
#include <cstdint>

#include "ReusingLDLT.h"
#include "LdltCompliance.h"
#include "core/Link.h"
#include "linalg/AssembledMatrix.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Direct sparse solver A = L D L^T (SOFA's SparseLDLSolver; also answers to SOFA's
/// EigenSimplicialLDLT and EigenSimplicialLLT, the same factorization). A = m M + b B + k K is
/// assembled at every solve (fixed degrees of freedom as identity rows); Eigen's
/// SimplicialLDLT factorizes it with a fill-reducing AMD ordering (Amestoy, Davis and Duff
/// 1996; up-looking LDL^T of Davis 2005, "Algorithm 849: a concise sparse Cholesky
/// factorization package"). The symbolic analysis (ordering, elimination tree, pattern of L)
/// is redone only when the matrix's sparsity pattern changed (AssembledMatrix::
/// patternRevision()); each solve refactorizes numerically.
///
/// The system of a mechanical step is symmetric positive definite: a pivot D_i <= 0 (or not
/// finite) is reported as an error naming the degree of freedom, and the solve returns zero.
class SparseLDLSolver final : public LinearSolver {
 public:
  Data<bool> d_parallelInverseProduct{this, "parallelInverseProduct", false,
                                      "SOFA option, accepted and without effect."};
  Link<Base> l_linearSystem{this, "linearSystem",
                            "SOFA option, accepted: Stroma assembles the system itself."};
  Data<int> d_symbolicAnalyses{this,
                               "symbolicAnalyses",
                               0,
                               "Symbolic analyses so far (one per sparsity pattern).",
                               {.output = true}};
  Data<int> d_factorizations{
      this, "factorizations", 0, "Numeric factorizations so far.", {.output = true}};
  Data<int> d_LNnz{
      this, "L_nnz", 0, "Non-zeros of the factor L of the last factorization.", {.output = true}};

  LinearSolveReport solve(MechanicalOperations& mop, const MechanicalParams& mp, VecId x,
                          VecId rhs) override;
  /// With the factorization of the last solve (one product by L^-T D^-1 L^-1 per call).
  bool solveWithLastMatrix(MechanicalOperations& mop, VecId x, VecId rhs) override;
  /// From the factors of the last solve, without a solve per row of J (LdltCompliance.h).
  bool addJMInvJt(MechanicalOperations& mop, const Eigen::SparseMatrix<double, Eigen::RowMajor>& J,
                  double factor, Eigen::MatrixXd& W) override;

 private:
  AssembledMatrix m_matrix;
  ReusingLDLT m_ldlt;
  bool m_reportedIndefinite = false;
  bool m_factorized = false;  ///< the last solve left a usable factorization
  std::uint64_t m_analyzedRevision = 0;  ///< patternRevision() of the analysis; 0: none
  LdltCompliance m_compliance;
  bool m_treeStale = true;  ///< a new analysis: the compliance's elimination tree is to be read
  Eigen::VectorXd m_rhs, m_solution;
};

}  // namespace stroma
