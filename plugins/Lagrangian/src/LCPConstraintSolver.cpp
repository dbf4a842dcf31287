// SPDX-License-Identifier: MIT
#include "LCPConstraintSolver.h"

#include "SolverSupport.h"
#include "core/Message.h"

namespace stroma {

void LCPConstraintSolver::init() { lagrangian::checkFreeMotionLoop(*this); }

void LCPConstraintSolver::cleanup() {
  lagrangian::unconvergedSummary(*this, m_counts, "maxIt");
}

ConstraintSolveReport LCPConstraintSolver::solve(const Eigen::MatrixXd& W,
                                                 const Eigen::VectorXd& violation,
                                                 std::span<const ConstraintGroup> groups,
                                                 Eigen::VectorXd& lambda) {
  lambda = Eigen::VectorXd::Zero(violation.size());
  const lagrangian::GaussSeidelSettings settings{.maxIterations = d_maxIt.value(),
                                                 .tolerance = d_tolerance.value(),
                                                 .sor = 1.0,
                                                 .muOverride = d_mu.value()};
  const ConstraintSolveReport report =
      lagrangian::solveProjectedGaussSeidel(W, violation, groups, settings, lambda);
  d_currentIterations.setValue(report.iterations);
  d_currentError.setValue(report.error);
  lagrangian::countSolve(*this, report, d_tolerance.value(), "maxIt", m_counts);
  return report;
}

}  // namespace stroma
