// SPDX-License-Identifier: MIT
#include "CholmodSolver.h"

#include <cholmod.h>

#include <cmath>
#include <cstring>

#include "simulation/SystemRows.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Timing.h"

namespace stroma {

namespace {

// A view of the lower triangle of a compressed column matrix, without copying it.
cholmod_sparse viewLower(const Eigen::SparseMatrix<double>& A) {
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<std::size_t>(A.rows());
  view.nzmax = static_cast<std::size_t>(A.nonZeros());
  view.p = const_cast<int*>(A.outerIndexPtr());
  view.i = const_cast<int*>(A.innerIndexPtr());
  view.x = const_cast<double*>(A.valuePtr());
  view.stype = -1;  // symmetric, lower triangle used
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

const char* statusText(int status) {
  switch (status) {
    case CHOLMOD_NOT_INSTALLED:
      return "a method this CHOLMOD build does not have";
    case CHOLMOD_OUT_OF_MEMORY:
      return "out of memory";
    case CHOLMOD_TOO_LARGE:
      return "integer overflow (the system is too large)";
    case CHOLMOD_INVALID:
      return "invalid input";
    default:
      return "CHOLMOD error";
  }
}

}  // namespace

CholmodSolver::CholmodSolver() : m_common(new cholmod_common) {
  cholmod_start(m_common);
  m_common->print = 0;  // library code never prints: failures are reported as messages
}

CholmodSolver::~CholmodSolver() {
  cholmod_free_factor(&m_factor, m_common);
  cholmod_free_dense(&m_x, m_common);
  cholmod_free_dense(&m_y, m_common);
  cholmod_free_dense(&m_e, m_common);
  cholmod_finish(m_common);
  delete m_common;
}

bool CholmodSolver::analyze() {
  cholmod_free_factor(&m_factor, m_common);
  switch (d_factorization.value()) {
    case CholmodFactorization::automatic:
      m_common->supernodal = CHOLMOD_AUTO;
      break;
    case CholmodFactorization::supernodal:
      m_common->supernodal = CHOLMOD_SUPERNODAL;
      break;
    case CholmodFactorization::simplicial:
      m_common->supernodal = CHOLMOD_SIMPLICIAL;
      break;
  }
  // LL^T for the simplicial factor too, so that an indefinite matrix fails in both forms.
  m_common->final_ll = 1;
  m_common->nmethods = 1;
  switch (d_permutation.value()) {
    case CholmodPermutation::none:
      m_common->method[0].ordering = CHOLMOD_NATURAL;
      break;
    case CholmodPermutation::suiteSparse:
      m_common->method[0].ordering = CHOLMOD_AMD;
      break;
    case CholmodPermutation::metis:
      m_common->method[0].ordering = CHOLMOD_METIS;
      break;
  }
  m_common->postorder = d_permutation.value() != CholmodPermutation::none;
  cholmod_sparse A = viewLower(m_matrix.matrix());
  m_factor = cholmod_analyze(&A, m_common);
  if (!m_factor) {
    msgError(std::string("the CHOLMOD symbolic analysis failed: ") + statusText(m_common->status) +
                 (d_permutation.value() == CholmodPermutation::metis
                      ? " (permutation METIS needs CHOLMOD built with METIS; use SuiteSparse)"
                      : ""),
             "permutation");
    return false;
  }
  m_analyzedRevision = m_matrix.patternRevision();
  d_symbolicAnalyses.setValue(d_symbolicAnalyses.value() + 1);
  d_LNnz.setValue(m_common->lnz);
  return true;
}

LinearSolveReport CholmodSolver::solve(MechanicalOperations& mop, const MechanicalParams& mp,
                                       VecId x, VecId rhs) {
  mop.assemble(mp, m_matrix);
  ScopedPhase phase(mop.timing(), "linearSolve");
  LinearSolveReport report;
  const Eigen::Index n = m_matrix.matrix().rows();
  auto fail = [&] {
    report.converged = false;
    report.residual = 1;
    mop.scatter(Eigen::VectorXd::Zero(n), x);
    return report;
  };
  if (n == 0) return report;
  std::size_t badRow = 0, badColumn = 0;
  if (findNonFiniteEntry(m_matrix.matrix(), badRow, badColumn)) {
    msgError(describeNonFiniteEntry(mop, badRow, badColumn));
    return fail();
  }

  // Symbolic analysis once per sparsity pattern, numeric factorization every solve.
  if ((!m_factor || m_matrix.patternRevision() != m_analyzedRevision) && !analyze()) return fail();
  cholmod_sparse A = viewLower(m_matrix.matrix());
  cholmod_factorize(&A, m_factor, m_common);
  d_factorizations.setValue(d_factorizations.value() + 1);
  d_supernodalFactor.setValue(m_factor->is_super != 0);
  if (m_common->status == CHOLMOD_NOT_POSDEF || m_factor->minor < m_factor->n) {
    // minor is the failing column of the permuted matrix; Perm maps it back.
    const std::size_t column = m_factor->minor;
    const auto* perm = static_cast<const int*>(m_factor->Perm);
    const auto row = static_cast<std::size_t>(perm ? perm[column] : static_cast<int>(column));
    msgError(
        "the CHOLMOD factorization failed: the system matrix is not positive definite "
        "(column of " +
        describeSystemRow(mop, row) +
        "). A point without mass, a "
        "stiffness of the wrong sign, or a static system that is not held in place make "
        "it singular or indefinite");
    return fail();
  }
  if (m_common->status < CHOLMOD_OK) {
    msgError(std::string("the CHOLMOD factorization failed: ") + statusText(m_common->status));
    return fail();
  }

  // L L^T x = b, through the reused workspaces.
  mop.gather(rhs, m_rhs);
  cholmod_dense b{};
  b.nrow = b.nzmax = b.d = static_cast<std::size_t>(n);
  b.ncol = 1;
  b.x = m_rhs.data();
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_solve2(CHOLMOD_A, m_factor, &b, nullptr, &m_x, nullptr, &m_y, &m_e, m_common)) {
    msgError(std::string("the CHOLMOD solve failed: ") + statusText(m_common->status));
    return fail();
  }
  m_solution = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(m_x->x), n);
  mop.scatter(m_solution, x);
  return report;
}

}  // namespace stroma
