// SPDX-License-Identifier: MIT
#include "LinearSolverConstraintCorrection.h"

#include "CorrectionSupport.h"
#include "core/Node.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Solvers.h"

namespace stroma {

void LinearSolverConstraintCorrection::init() {
  Base* target = l_linearSolver.get();
  if (auto* n = dynamic_cast<Node*>(target)) target = n->get<LinearSolver>();
  m_solver = target ? dynamic_cast<LinearSolver*>(target)
                    : (node() ? node()->getUp<LinearSolver>() : nullptr);
  if (!m_solver)
    msgError(l_linearSolver ? l_linearSolver->path() + " is not a linear solver"
                            : "needs a linear solver (CGLinearSolver, SparseLDLSolver) in its node "
                              "or above, or a 'linearSolver' link",
             "linearSolver");
}

void LinearSolverConstraintCorrection::addCompliance(
    MechanicalOperations& mop, const ConstraintResponse& response,
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& H, Eigen::MatrixXd& W) {
  if (!m_solver) return;
  const double factor = d_complianceFactor.value() * response.positionFactor;
  // A direct solver gives H A^-1 H^T from its factors; otherwise one solve per row, U = A^-1 H^T
  // kept for the correction.
  m_rows = H.rows();
  m_direct = m_solver->addJMInvJt(mop, H, factor, W);
  if (!m_direct) {
    const auto n = static_cast<Eigen::Index>(mop.systemSize());
    m_U.resize(n, H.rows());
    const VecId rhs = mop.allocDeriv(), solution = mop.allocDeriv();
    for (Eigen::Index r = 0; r < H.rows(); ++r) {
      m_rhs = H.row(r).transpose();
      mop.scatter(m_rhs, rhs);
      mop.projectResponse(rhs);
      if (!m_solver->solveWithLastMatrix(mop, solution, rhs))
        m_solver->solve(mop, response.matrix, solution, rhs);
      mop.projectResponse(solution);
      mop.gather(solution, m_column);
      m_U.col(r) = m_column;
    }
    mop.freeVec(rhs);
    mop.freeVec(solution);
    W += factor * (H * m_U);
  }
  if (const double regularization = d_regularizationTerm.value(); regularization > 0)
    for (Eigen::Index r = 0; r < H.rows(); ++r)
      if (H.row(r).nonZeros() > 0) W(r, r) += regularization;
}

void LinearSolverConstraintCorrection::applyCorrection(
    MechanicalOperations& mop, const ConstraintResponse& response,
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& H, const Eigen::VectorXd& lambda) {
  if (!m_solver || m_rows != H.rows()) return;
  if (m_direct) {
    // dx = A^-1 H^T lambda: one solve with the factors of the compliance.
    m_rhs.noalias() = H.transpose() * lambda;
    m_rhs *= d_complianceFactor.value();
    const VecId rhs = mop.allocDeriv(), solution = mop.allocDeriv();
    mop.scatter(m_rhs, rhs);
    mop.projectResponse(rhs);
    const bool solved = m_solver->solveWithLastMatrix(mop, solution, rhs);
    mop.projectResponse(solution);
    mop.gather(solution, m_correction);
    mop.freeVec(rhs);
    mop.freeVec(solution);
    if (!solved) return;
  } else {
    m_correction = d_complianceFactor.value() * (m_U * lambda);
  }
  lagrangian::moveStates(mop, response, m_correction);
}

}  // namespace stroma
