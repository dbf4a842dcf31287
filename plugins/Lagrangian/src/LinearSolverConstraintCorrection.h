// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "core/Data.h"
#include "core/Link.h"
#include "simulation/Constraints.h"
#include "simulation/Solvers.h"

namespace stroma {

/// SOFA's LinearSolverConstraintCorrection and GenericConstraintCorrection: the compliance of
/// the solver's states through its own system A (the matrix of its last step, mass, damping and
/// stiffness: Constraints.h's ConstraintResponse):
///   U = A^-1 H^T (one solve per constraint row),   W += positionFactor complianceFactor H U,
///   or, from a direct solver's factors (LinearSolver::addJMInvJt: SparseLDLSolver), W alone
///   and then dx = A^-1 H^T lambda with one solve;
///   dx = positionFactor complianceFactor U lambda,   dv = velocityFactor complianceFactor U
///   lambda.
/// `regularizationTerm` is added to W's diagonal on the rows that act on these states.
/// The linear solver is the `linearSolver` link, else the one in the ODE solver's node.
class LinearSolverConstraintCorrection final : public BaseConstraintCorrection {
 public:
  Link<Base> l_linearSolver{this, "linearSolver",
                            "The linear solver (default: the one in this node)."};
  Data<double> d_complianceFactor{this, "complianceFactor", 1.0,
                                  "Factor of the compliance (and of the correction).",
                                  {.min = 0.0}};
  Data<double> d_regularizationTerm{this,
                                    "regularizationTerm",
                                    0.0,
                                    "Added to the diagonal of W on the rows acting on this body "
                                    "(a redundant or singular set of constraints becomes "
                                    "solvable).",
                                    {.unit = "m/N", .min = 0.0}};

  void init() override;
  void addCompliance(MechanicalOperations& mop, const ConstraintResponse& response,
                     const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                     Eigen::MatrixXd& W) override;
  void applyCorrection(MechanicalOperations& mop, const ConstraintResponse& response,
                       const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                       const Eigen::VectorXd& lambda) override;

 private:
  LinearSolver* m_solver = nullptr;
  Eigen::MatrixXd m_U;  // A^-1 H^T of the last compliance, when solved row by row
  bool m_direct = false;  // the last compliance came from the solver's factors (addJMInvJt)
  Eigen::Index m_rows = -1;  // rows of the last compliance
  Eigen::VectorXd m_rhs, m_column, m_correction;
};

}  // namespace stroma
