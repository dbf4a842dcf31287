// SPDX-License-Identifier: MIT
#include "GenericConstraintSolver.h"

#include "SolverSupport.h"
#include "core/Message.h"

namespace stroma {

void GenericConstraintSolver::init() {
  lagrangian::checkFreeMotionLoop(*this);
  const std::string& method = d_resolutionMethod.value();
  m_conjugateGradient = method == "NonsmoothNonlinearConjugateGradient";
  if (method != "ProjectedGaussSeidel" && method != "UnbuiltGaussSeidel" && !m_conjugateGradient)
    msgError("resolutionMethod '" + method +
                 "' is not one of ProjectedGaussSeidel, UnbuiltGaussSeidel, "
                 "NonsmoothNonlinearConjugateGradient",
             "resolutionMethod");
}

void GenericConstraintSolver::cleanup() {
  lagrangian::unconvergedSummary(*this, m_counts, "maxIterations");
}

ConstraintSolveReport GenericConstraintSolver::solve(const Eigen::MatrixXd& W,
                                                     const Eigen::VectorXd& violation,
                                                     std::span<const ConstraintGroup> groups,
                                                     Eigen::VectorXd& lambda) {
  lambda = m_last.size() == violation.size() ? m_last : Eigen::VectorXd::Zero(violation.size());
  const lagrangian::GaussSeidelSettings settings{.maxIterations = d_maxIterations.value(),
                                                 .tolerance = d_tolerance.value(),
                                                 .sor = d_sor.value(),
                                                 .regularization = d_regularizationTerm.value()};
  const ConstraintSolveReport report =
      m_conjugateGradient
          ? lagrangian::solveNonsmoothConjugateGradient(W, violation, groups, settings, lambda)
          : lagrangian::solveProjectedGaussSeidel(W, violation, groups, settings, lambda);
  m_last = lambda;
  d_currentIterations.setValue(report.iterations);
  d_currentError.setValue(report.error);
  d_constraintForces.edit().assign(lambda.data(), lambda.data() + lambda.size());
  lagrangian::countSolve(*this, report, d_tolerance.value(), "maxIterations", m_counts);
  return report;
}

}  // namespace stroma
