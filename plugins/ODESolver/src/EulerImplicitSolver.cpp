// SPDX-License-Identifier: MIT
#include "EulerImplicitSolver.h"

#include <cmath>

#include "StepChecks.h"
#include "core/Node.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

void EulerImplicitSolver::init() {
  if (!l_linearSolver && node()) l_linearSolver.set(node()->get<LinearSolver>());
  if (d_trapezoidalScheme.value())
    msgWarning("the trapezoidal scheme is not implemented; backward Euler is used",
               "trapezoidalScheme");
  if (!l_linearSolver)
    msgError("needs a linear solver in its node (CGLinearSolver, SparseLDLSolver, ...)",
             "linearSolver");
}

void EulerImplicitSolver::computeResidual(MechanicalOperations& mop, double h, VecId r, VecId mvn) {
  const VecId x = VecId::position(), v = VecId::velocity(), f = VecId::force();
  mop.propagate(x, v);
  MechanicalParams mp;
  mp.dt = h;
  mop.computeForce(mp, f);
  MechanicalParams terms;
  terms.dt = h;
  if (d_firstOrder.value()) {
    terms.mFactor = -h;  // -M (x - x_n) = -h M v
    terms.kFactor = 0;
    mop.computeMBKdx(terms, r, v);
  } else {
    terms.mFactor = -(1.0 + h * d_rayleighMass.value());
    terms.kFactor = h * d_rayleighStiffness.value();
    mop.computeMBKdx(terms, r, v);
    mop.vOp(r, r, mvn, 1.0);
  }
  mop.vOp(r, r, f, h);
  mop.projectResponse(r);
}

void EulerImplicitSolver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState() || !checkTimeStep(*this, dt)) return;
  ++m_step;
  const double h = dt;
  const double rm = d_rayleighMass.value(), rs = d_rayleighStiffness.value();
  const bool firstOrder = d_firstOrder.value();
  const int newtonIterations = d_newtonIterations.value();
  const VecId x = VecId::position(), v = VecId::velocity(), f = VecId::force();
  const VecId b = mop.allocDeriv(), dv = mop.allocDeriv(), tmp = mop.allocDeriv();

  // Right-hand side: b = h [f + (h + rs) K v - rm M v]  (first order: b = h f).
  MechanicalParams mp;
  mp.dt = h;
  mop.computeForce(mp, f);
  mop.vOp(b, VecId::null(), f, h);
  if (!firstOrder) {
    MechanicalParams damping;
    damping.mFactor = -rm;
    damping.kFactor = h + rs;
    mop.computeMBKdx(damping, tmp, v);
    mop.vOp(b, b, tmp, h);
  }
  mop.projectResponse(b);

  // Matrix: (1 + h rm) M - h (h + rs) K   (first order: M - h K).
  MechanicalParams matrix;
  matrix.dt = h;
  matrix.mFactor = firstOrder ? 1.0 : 1.0 + h * rm;
  matrix.kFactor = firstOrder ? -h : -h * (h + rs);
  matrix.bFactor = 0;

  // M v_n, for the residuals of the Newton iterations.
  VecId mvn = VecId::null();
  if (newtonIterations > 1 || d_computeResidual.value()) {
    mvn = mop.allocDeriv();
    MechanicalParams massOnly;
    massOnly.mFactor = 1.0;
    massOnly.kFactor = 0.0;
    mop.computeMBKdx(massOnly, mvn, v);
  }
  const double normB = mop.norm(b);
  const double scale = normB > 0 ? normB : 1.0;

  // Linearized step.
  mop.vOp(dv, VecId::null(), VecId::null(), 0.0);
  const LinearSolveReport first = l_linearSolver->solve(mop, matrix, dv, b);
  if (!checkLinearSolve(mop, m_divergence, m_linear, first, *l_linearSolver.get(), m_step, dv))
    return;
  if (firstOrder) {
    mop.vOp(v, VecId::null(), dv, 1.0 / h);
    mop.vOp(x, x, dv, 1.0);
  } else {
    mop.vOp(v, v, dv, 1.0);
    mop.vOp(x, x, v, h);
  }
  int solves = 1;

  // Newton iterations on the residual, x and v moving together (dx = h dv).
  double residual = -1;
  if (newtonIterations > 1) {
    double previous = -1;  // the residual before the last solve
    bool lastLowered = true;
    while (true) {
      computeResidual(mop, h, tmp, mvn);
      residual = mop.norm(tmp) / scale;
      if (previous >= 0) lastLowered = residual < previous;
      if (residual <= d_newtonTolerance.value() || solves >= newtonIterations) break;
      previous = residual;
      mop.vOp(dv, VecId::null(), VecId::null(), 0.0);
      const LinearSolveReport next = l_linearSolver->solve(mop, matrix, dv, tmp);
      if (!checkLinearSolve(mop, m_divergence, m_linear, next, *l_linearSolver.get(), m_step, dv))
        return;
      if (firstOrder) {
        mop.vOp(x, x, dv, 1.0);
        mop.vOp(v, v, dv, 1.0 / h);
      } else {
        mop.vOp(v, v, dv, 1.0);
        mop.vOp(x, x, dv, h);
      }
      ++solves;
    }
    if (residual > d_newtonTolerance.value() && m_unconverged++ == 0)
      msgWarning("Newton did not converge in " + std::to_string(solves) + " iterations at step " +
                     std::to_string(m_step) + ": relative residual " + std::to_string(residual) +
                     " > newtonTolerance " + std::to_string(d_newtonTolerance.value()) +
                     " (raise newtonIterations or lower dt); later ones are counted",
                 "newtonIterations");
    // A stall: Newton ended unconverged without progress (|r| is in tmp).
    if (residual > d_newtonTolerance.value() && (!lastLowered || !(residual < 1))) {
      const std::string reason = "Newton stopped after " + std::to_string(solves) +
                                 " linear solves with relative "
                                 "residual " +
                                 formatNumber(residual) +
                                 (lastLowered ? ", not below the first right-hand side's"
                                              : ", the last iteration having raised it") +
                                 " (lower dt: the step is too nonlinear for the linearized matrix)";
      if (!m_divergence.report(mop, DivergenceKind::newtonStall, m_step, reason,
                               mop.describeWorstVertex(tmp, "residual"), "newtonIterations"))
        return;
    }
  } else if (d_computeResidual.value()) {
    computeResidual(mop, h, tmp, mvn);
    residual = mop.norm(tmp) / scale;
  }
  d_lastIterations.setValue(solves);
  if (residual >= 0) {
    d_lastResidual.setValue(residual);
    if (d_printLog.value())
      msgInfo("step " + std::to_string(m_step) + ": " + std::to_string(solves) +
              " linear solve(s), relative residual " + std::to_string(residual));
  }

  if (d_vdamping.value() > 0) mop.vOp(v, VecId::null(), v, std::exp(-h * d_vdamping.value()));
  mop.projectPosition(x);
  mop.projectVelocity(v);
  finishStep(mop, *this, m_step, m_divergence, &m_energy);
}

void EulerImplicitSolver::cleanup() {
  m_divergence.summarize(m_step);
  if (m_unconverged > 1)
    msgWarning("Newton did not converge in " + std::to_string(m_unconverged) + " of " +
                   std::to_string(m_step) + " steps",
               "newtonIterations");
}

bool EulerImplicitSolver::constraintResponse(double dt, ConstraintResponse& response) const {
  // The solved increment is dv (x moves by h dv) with the matrix of solve(); first order: the
  // increment is dx itself (v = dx / h).
  const double h = dt;
  const double rm = d_rayleighMass.value(), rs = d_rayleighStiffness.value();
  const bool firstOrder = d_firstOrder.value();
  response.matrix = MechanicalParams{};
  response.matrix.dt = h;
  response.matrix.mFactor = firstOrder ? 1.0 : 1.0 + h * rm;
  response.matrix.kFactor = firstOrder ? -h : -h * (h + rs);
  response.matrix.bFactor = 0;
  response.positionFactor = firstOrder ? h : h * h;
  response.velocityFactor = firstOrder ? 1.0 : h;
  return true;
}

}  // namespace stroma
