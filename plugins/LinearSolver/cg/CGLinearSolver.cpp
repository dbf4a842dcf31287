// SPDX-License-Identifier: MIT
#include "CGLinearSolver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "simulation/DependentDofs.h"
#include "simulation/ProjectiveConstraint.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Timing.h"

namespace stroma {

namespace {

// A positive p.Ap below the scene's threshold is SOFA's way of stopping CG once the step left
// is negligible: the solve ends as the scene asked, not diverged (the ODE solvers do not count
// it). Zero, negative or non-finite p.Ap is a breakdown: the matrix is not positive definite.
bool stoppedOnThreshold(double denominator, double threshold) {
  return std::isfinite(denominator) && denominator > 0 && denominator < threshold;
}

bool isAssembledTemplate(const std::string& name) {
  return name.rfind("CompressedRowSparseMatrix", 0) == 0;
}

// The DependentDofs hooks (T-nodes): projective constraints of the system that also interpolate
// some of its independent dofs from others.
void collectDependentDofs(const MechanicalOperations& mop, std::vector<DependentDofs*>& found) {
  found.clear();
  const auto& states = mop.independentStates();
  for (BaseProjectiveConstraint* c : mop.constraints())
    if (auto* hook = dynamic_cast<DependentDofs*>(c);
        hook && std::find(states.begin(), states.end(), hook->dependentState()) != states.end())
      found.push_back(hook);
}
}  // namespace

void CGLinearSolver::init() {
  m_assembled = isAssembledTemplate(templateName());
  if (d_maxIter.isSet() && !d_iterations.isSet()) d_iterations.setValue(d_maxIter.value());
  if (d_smallDenominatorThreshold.isSet() && !d_threshold.isSet())
    d_threshold.setValue(d_smallDenominatorThreshold.value());
  if (d_jacobiPreconditioner.value() && !isAssembledTemplate(templateName()))
    msgWarning(
        "the Jacobi preconditioner needs the assembled matrix: it is ignored with "
        "template " +
            templateName() + " (use template=\"CompressedRowSparseMatrixMat3x3d\")",
        "jacobiPreconditioner");
}

LinearSolveReport CGLinearSolver::solve(MechanicalOperations& mop, const MechanicalParams& mp,
                                        VecId x, VecId rhs) {
  const bool assembled = m_assembled;
  m_brokeDown = false;
  LinearSolveReport r =
      assembled ? solveAssembled(mop, mp, x, rhs) : solveMatrixFree(mop, mp, x, rhs);
  report(r);
  return r;
}

LinearSolveReport CGLinearSolver::solveMatrixFree(MechanicalOperations& mop,
                                                  const MechanicalParams& mp, VecId x, VecId rhs) {
  ScopedPhase phase(mop.timing(), "linearSolve");
  std::vector<DependentDofs*>& dependent = m_dependent;  // kept: no list allocated per solve
  collectDependentDofs(mop, dependent);
  LinearSolveReport report;
  const VecId r = mop.allocDeriv(), p = mop.allocDeriv(), q = mop.allocDeriv();
  const double normB = mop.norm(rhs);
  if (normB == 0) {
    mop.vOp(x, VecId::null(), VecId::null(), 0.0);
    return report;
  }
  // r = rhs - A x
  if (d_warmStart.value()) {
    for (DependentDofs* d : dependent) d->interpolateDependent(x);
    mop.computeMBKdx(mp, q, x);
    mop.projectResponse(q);
    mop.vOp(r, rhs, q, -1.0);
  } else {
    mop.vOp(x, VecId::null(), VecId::null(), 0.0);
    mop.vOp(r, rhs);
  }
  mop.vOp(p, r);
  double rho = mop.dot(r, r);
  const int maxIterations = d_iterations.value();
  const double tolerance = d_tolerance.value(), threshold = d_threshold.value();
  report.converged = false;
  while (true) {
    report.residual = std::sqrt(rho) / normB;
    if (report.residual <= tolerance) {
      report.converged = true;
      break;
    }
    if (report.iterations >= maxIterations) break;
    for (DependentDofs* d : dependent) d->interpolateDependent(p);
    mop.computeMBKdx(mp, q, p);
    mop.projectResponse(q);
    const double den = mop.dot(p, q);
    if (std::abs(den) < threshold || !std::isfinite(den)) {
      m_brokeDown = true;
      m_lastDenominator = den;
      report.converged = stoppedOnThreshold(den, threshold);
      break;
    }
    const double alpha = rho / den;
    mop.vOp(x, x, p, alpha);
    mop.vOp(r, r, q, -alpha);
    const double rhoNext = mop.dot(r, r);
    mop.vOp(p, r, p, rhoNext / rho);
    rho = rhoNext;
    ++report.iterations;
  }
  for (DependentDofs* d : dependent) d->clearDependent(x);
  mop.freeVec(q);
  mop.freeVec(p);
  mop.freeVec(r);
  return report;
}

LinearSolveReport CGLinearSolver::solveAssembled(MechanicalOperations& mop,
                                                 const MechanicalParams& mp, VecId x, VecId rhs) {
  mop.assemble(mp, m_matrix);
  ScopedPhase phase(mop.timing(), "linearSolve");
  const Eigen::SparseMatrix<double>& A = m_matrix.matrix();
  Eigen::VectorXd b, solution;
  mop.gather(rhs, b);
  if (d_warmStart.value())
    mop.gather(x, solution);
  else
    solution = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd inverseDiagonal = Eigen::VectorXd::Ones(b.size());
  if (d_jacobiPreconditioner.value()) {
    const Eigen::VectorXd d = A.diagonal();
    for (Eigen::Index i = 0; i < d.size(); ++i) inverseDiagonal[i] = d[i] != 0 ? 1.0 / d[i] : 1.0;
  }
  LinearSolveReport report;
  const double normB = b.norm();
  if (normB == 0) {
    mop.scatter(Eigen::VectorXd::Zero(b.size()), x);
    return report;
  }
  Eigen::VectorXd r = b - A * solution;
  Eigen::VectorXd z = inverseDiagonal.cwiseProduct(r);
  Eigen::VectorXd p = z, q(b.size());
  double rho = r.dot(z);
  report.converged = false;
  while (true) {
    report.residual = r.norm() / normB;
    if (report.residual <= d_tolerance.value()) {
      report.converged = true;
      break;
    }
    if (report.iterations >= d_iterations.value()) break;
    q.noalias() = A * p;
    const double den = p.dot(q);
    if (std::abs(den) < d_threshold.value() || !std::isfinite(den)) {
      m_brokeDown = true;
      m_lastDenominator = den;
      report.converged = stoppedOnThreshold(den, d_threshold.value());
      break;
    }
    const double alpha = rho / den;
    solution += alpha * p;
    r -= alpha * q;
    z = inverseDiagonal.cwiseProduct(r);
    const double rhoNext = r.dot(z);
    p = z + (rhoNext / rho) * p;
    rho = rhoNext;
    ++report.iterations;
  }
  mop.scatter(solution, x);
  return report;
}

void CGLinearSolver::report(const LinearSolveReport& r) {
  ++m_solves;
  d_lastIterations.setValue(r.iterations);
  d_lastResidual.setValue(r.residual);
  if (d_verbose.value())
    msgInfo("CG: " + std::to_string(r.iterations) + " iterations, relative residual " +
            std::to_string(r.residual));
  // A stop on the threshold is reported even when it counts as converged (the scene's stop).
  if (r.converged && !m_brokeDown) return;
  if (m_unconverged++ == 0) {
    const auto number = [](double value) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g", value);
      return std::string(text);
    };
    std::string why = "CG stopped after " + std::to_string(r.iterations) + " iterations";
    if (m_brokeDown)
      why += ", when p.Ap = " + number(m_lastDenominator) + " fell below threshold " +
             number(d_threshold.value()) + ",";
    why += " without converging: relative residual " + number(r.residual) + " > tolerance " +
           number(d_tolerance.value());
    if (r.residual > 1)
      why +=
          ", above the right-hand side's norm: the iterates moved away, as on an indefinite "
          "matrix (an element inverted, a tangent that is not the forces' derivative)";
    why += m_brokeDown ? " (lower threshold, or check the system)"
                       : " (raise iterations, or check the system)";
    msgWarning(why + "; later ones are counted", m_brokeDown ? "threshold" : "iterations");
  }
  m_brokeDown = false;
}

void CGLinearSolver::cleanup() {
  if (m_unconverged > 1)
    msgWarning("CG did not converge in " + std::to_string(m_unconverged) + " of " +
                   std::to_string(m_solves) + " solves",
               "iterations");
}

}  // namespace stroma
