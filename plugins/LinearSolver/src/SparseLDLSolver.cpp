// SPDX-License-Identifier: MIT
#include "SparseLDLSolver.h"

#include <cmath>
#include <cstdio>

#include "simulation/SystemRows.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Timing.h"

namespace stroma {

LinearSolveReport SparseLDLSolver::solve(MechanicalOperations& mop, const MechanicalParams& mp,
                                         VecId x, VecId rhs) {
  m_factorized = false;
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
    m_treeStale = true;
    d_symbolicAnalyses.setValue(d_symbolicAnalyses.value() + 1);
  }
  m_ldlt.factorize(A);
  d_factorizations.setValue(d_factorizations.value() + 1);

  // A failed or singular factorization: report the first bad pivot where the user can find
  // it (D is in the permuted order; P^-1 maps it back to the system's rows). A pivot is bad
  // when it is zero, not finite, or negligible next to the largest one (a singular system in
  // floating point). Negative pivots alone are not an error: LDL^T solves a symmetric
  // indefinite system exactly (a compressed spring or a buckling element makes K indefinite),
  // but the user is told once, since a dynamic system matrix should be positive definite.
  const Eigen::VectorXd& D = m_ldlt.vectorD();
  // A failed factorization stops at its first zero pivot and leaves the later entries of D
  // unwritten (whatever the memory held): only the pivots up to that one are read.
  Eigen::Index computed = D.size();
  if (m_ldlt.info() != Eigen::Success)
    for (Eigen::Index k = 0; k < D.size(); ++k)
      if (D[k] == 0.0 || !std::isfinite(D[k])) {
        computed = k + 1;
        break;
      }
  const double largestPivot = computed > 0 ? D.head(computed).cwiseAbs().maxCoeff() : 0.0;
  Eigen::Index bad = -1, negative = -1;
  for (Eigen::Index k = 0; k < computed && bad < 0; ++k) {
    if (!std::isfinite(D[k]) || std::abs(D[k]) <= 1e-14 * largestPivot)
      bad = k;
    else if (D[k] < 0 && negative < 0)
      negative = k;
  }
  if (m_ldlt.info() != Eigen::Success && bad < 0) bad = 0;
  const auto describePivot = [&](Eigen::Index k) {
    const auto row = static_cast<std::size_t>(m_ldlt.permutationPinv().indices()[k]);
    char pivot[32];
    std::snprintf(pivot, sizeof pivot, "%.6g", k < D.size() ? D[k] : 0.0);
    return "pivot D = " + std::string(pivot) + " at " + describeSystemRow(mop, row);
  };
  if (bad >= 0 || A.rows() == 0) {
    if (bad >= 0) {
      msgError("the LDL^T factorization failed: the system matrix is singular (" +
               describePivot(bad) +
               "). A point without mass, a stiffness of the wrong sign, or a static system "
               "that is not held in place make it singular");
      report.converged = false;
      report.residual = 1;
    }
    mop.scatter(Eigen::VectorXd::Zero(A.rows()), x);
    return report;
  }
  if (negative >= 0 && !m_reportedIndefinite) {
    m_reportedIndefinite = true;
    msgWarning("the system matrix is indefinite (" + describePivot(negative) +
               "); LDL^T still solves it, but a negative stiffness (compressed springs, "
               "buckling or inverted elements) larger than the mass term can make the "
               "integration unstable; reported once");
  }
  d_LNnz.setValue(static_cast<int>(m_ldlt.matrixL().nestedExpression().nonZeros()));
  m_factorized = true;
  if (m_treeStale) {
    m_compliance.setFactor(m_ldlt.matrixL().nestedExpression());
    m_treeStale = false;
  }

  mop.gather(rhs, m_rhs);
  m_solution = m_ldlt.solve(m_rhs);
  mop.scatter(m_solution, x);
  return report;
}

bool SparseLDLSolver::solveWithLastMatrix(MechanicalOperations& mop, VecId x, VecId rhs) {
  if (!m_factorized || static_cast<std::size_t>(m_ldlt.rows()) != mop.systemSize()) return false;
  mop.gather(rhs, m_rhs);
  m_solution = m_ldlt.solve(m_rhs);
  mop.scatter(m_solution, x);
  return true;
}

bool SparseLDLSolver::addJMInvJt(MechanicalOperations& mop,
                                 const Eigen::SparseMatrix<double, Eigen::RowMajor>& J,
                                 double factor, Eigen::MatrixXd& W) {
  if (!m_factorized || static_cast<std::size_t>(m_ldlt.rows()) != mop.systemSize()) return false;
  ScopedPhase phase(mop.timing(), "linearSolve");
  return m_compliance.add(m_ldlt.matrixL().nestedExpression(), m_ldlt.vectorD(),
                          m_ldlt.permutationP().indices(), J, factor, W);
}

}  // namespace stroma
