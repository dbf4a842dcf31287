// SPDX-License-Identifier: MIT
// Solving one system with every linear solver of a node, for the solver comparisons.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "core/Node.h"
#include "plugins/ODESolver/SolverTestSupport.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Solvers.h"

namespace stroma::test {

/// The matrix of an implicit Euler step, (1 + h rm) M - h (h + rs) K, with h = 0.01 s.
inline MechanicalParams implicitEulerMatrix(double h = 0.01, double rm = 0.1, double rs = 0.1) {
  MechanicalParams mp;
  mp.dt = h;
  mp.mFactor = 1 + h * rm;
  mp.kFactor = -h * (h + rs);
  return mp;
}

struct Solutions {
  std::vector<Eigen::VectorXd> x;  ///< one per linear solver of the node, in scene order
  std::vector<double> residual;    ///< ||A x - b|| / ||b|| with the matrix-free product
  std::vector<LinearSolveReport> report;
};

/// Solves A x = b, b a fixed pseudo-random vector (projected), with each linear solver of the
/// body node; checks each solution against the matrix-free product A x.
inline Solutions solveWithEach(SolverScene& s, const MechanicalParams& mp) {
  Node& body = s.body();
  MechanicalOperations mop(body, s.scene().timing());
  const VecId rhs = mop.allocDeriv(), x = mop.allocDeriv(), product = mop.allocDeriv();
  Eigen::VectorXd b(static_cast<Eigen::Index>(mop.systemSize()));
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::sin(1.7 * static_cast<double>(i) + 0.3);
  mop.scatter(b, rhs);
  mop.projectResponse(rhs);
  // Forces first: components that cache per-state data (rotations) refresh it there.
  mop.computeForce(MechanicalParams{}, VecId::force());
  Solutions out;
  for (LinearSolver* solver : body.getAll<LinearSolver>()) {
    mop.vOp(x, VecId::null(), VecId::null(), 0.0);
    out.report.push_back(solver->solve(mop, mp, x, rhs));
    Eigen::VectorXd solution;
    mop.gather(x, solution);
    out.x.push_back(solution);
    mop.computeMBKdx(mp, product, x);
    mop.projectResponse(product);
    mop.vOp(product, product, rhs, -1.0);
    out.residual.push_back(mop.norm(product) / mop.norm(rhs));
  }
  return out;
}

inline double relativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).norm() / b.norm();
}

}  // namespace stroma::test
