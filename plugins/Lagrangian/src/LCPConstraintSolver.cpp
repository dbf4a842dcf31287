// SPDX-License-Identifier: MIT
#include "LCPConstraintSolver.h"

#include "SolverSupport.h"
#include "core/Message.h"

namespace stroma {

void LCPConstraintSolver::init() { lagrangian::checkFreeMotionLoop(*this); }

void LCPConstraintSolver::cleanup() {
  if (m_unconverged > 1)
    msgWarning("stopped unconverged in " + std::to_string(m_unconverged) + " of " +
                   std::to_string(m_solves) + " solves",
               "maxIt");
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
  ++m_solves;
  d_currentIterations.setValue(report.iterations);
  d_currentError.setValue(report.error);
  if (!report.converged && m_unconverged++ == 0)
    msgWarning("stopped after " + std::to_string(report.iterations) +
                   " iterations without converging: error " + formatNumber(report.error) +
                   " > tolerance " + formatNumber(d_tolerance.value()) +
                   " (raise maxIt or the tolerance); later ones are counted",
               "maxIt");
  return report;
}

}  // namespace stroma
