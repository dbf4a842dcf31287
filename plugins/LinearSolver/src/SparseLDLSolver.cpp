// SPDX-License-Identifier: MIT
#include "SparseLDLSolver.h"

#include <cmath>
#include <cstdio>

#include "SystemRows.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Timing.h"

namespace stroma {

LinearSolveReport SparseLDLSolver::solve(MechanicalOperations& mop, const MechanicalParams& mp,
                                         VecId x, VecId rhs) {
  mop.assemble(mp, m_matrix);
  ScopedPhase phase(mop.timing(), "linearSolve");
  const Eigen::SparseMatrix<double>& A = m_matrix.matrix();
  LinearSolveReport report;
  std::size_t badRow = 0, badColumn = 0;
  if (findNonFiniteEntry(A, badRow, badColumn)) {
    msgError(describeNonFiniteEntry(mop, badRow, badColumn));
    report.converged = false;
    report.residual = 1;
    mop.scatter(Eigen::VectorXd::Zero(A.rows()), x);
    return report;
  }

  // Symbolic analysis once per sparsity pattern, numeric factorization every solve.
  if (m_matrix.patternRevision() != m_analyzedRevision) {
    m_ldlt.analyzePattern(A);
    m_analyzedRevision = m_matrix.patternRevision();
    d_symbolicAnalyses.setValue(d_symbolicAnalyses.value() + 1);
  }
  m_ldlt.factorize(A);
  d_factorizations.setValue(d_factorizations.value() + 1);

  // A failed or indefinite factorization: report the first bad pivot where the user can find
  // it (D is in the permuted order; P^-1 maps it back to the system's rows).
  const Eigen::VectorXd& D = m_ldlt.vectorD();
  Eigen::Index bad = -1;
  if (m_ldlt.info() == Eigen::Success) {
    for (Eigen::Index k = 0; k < D.size() && bad < 0; ++k)
      if (!(D[k] > 0) || !std::isfinite(D[k])) bad = k;
  } else {
    for (Eigen::Index k = 0; k < D.size() && bad < 0; ++k)
      if (D[k] == 0 || !std::isfinite(D[k])) bad = k;
    if (bad < 0) bad = 0;
  }
  if (bad >= 0 || A.rows() == 0) {
    if (bad >= 0) {
      const auto row = static_cast<std::size_t>(m_ldlt.permutationPinv().indices()[bad]);
      char pivot[32];
      std::snprintf(pivot, sizeof pivot, "%.6g", bad < D.size() ? D[bad] : 0.0);
      msgError(
          "the LDL^T factorization failed: the system matrix is not positive definite "
          "(pivot D = " +
          std::string(pivot) + " at " + describeSystemRow(mop, row) +
          "). A point without mass, a stiffness of the wrong sign, or a static system "
          "that is not held in place make it singular or indefinite");
      report.converged = false;
      report.residual = 1;
    }
    mop.scatter(Eigen::VectorXd::Zero(A.rows()), x);
    return report;
  }
  d_LNnz.setValue(static_cast<int>(m_ldlt.matrixL().nestedExpression().nonZeros()));

  mop.gather(rhs, m_rhs);
  m_solution = m_ldlt.solve(m_rhs);
  mop.scatter(m_solution, x);
  return report;
}

}  // namespace stroma
