// SPDX-License-Identifier: MIT
#include "StaticSolver.h"

#include <cmath>

#include "StepChecks.h"
#include "core/Node.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

namespace {

// R = f(x) at the current positions (zero velocities), projected; returns |R|.
double residual(MechanicalOperations& mop, double dt, VecId r) {
  mop.propagate(VecId::position(), VecId::velocity());
  MechanicalParams mp;
  mp.dt = dt;
  mop.computeForce(mp, r);
  mop.projectResponse(r);
  return mop.norm(r);
}

// |R| / |R_0| below which the residual is round-off: the line search then cannot fail.
constexpr double kRoundoff = 1e-12;

}  // namespace

void StaticSolver::init() {
  if (!l_linearSolver && node()) l_linearSolver.set(node()->get<LinearSolver>());
  if (!l_linearSolver)
    msgError("needs a linear solver in its node (SparseLDLSolver, CGLinearSolver, ...)",
             "linearSolver");
}

NewtonSettings StaticSolver::settings() const {
  if (l_newtonSolver) return l_newtonSolver->settings();
  NewtonSettings s;
  s.iterations = d_newtonIterations.value();
  s.absoluteResidual = d_absoluteResidual.value();
  s.relativeInitial = d_relativeResidual.value();
  s.relativeSuccessive = 0;
  s.absoluteCorrection = d_absoluteCorrection.value();
  s.relativeCorrection = d_relativeCorrection.value();
  s.lineSearchTrials = d_lineSearchIterations.value();
  s.lineSearchCoefficient = 0.5;
  s.fullStepWhenLineSearchFails = false;
  s.stopWhenResidualGrows = d_shouldDiverge.value();
  // Newton is a load-stepping scheme with one iteration: not converging then is expected.
  s.warnWhenNotConverged = s.iterations > 1;
  return s;
}

void StaticSolver::setStatus(const char* status) {
  if (l_newtonSolver) l_newtonSolver->d_status.setValue(status);
}

void StaticSolver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState() || !checkTimeStep(*this, dt)) return;
  ++m_step;
  const NewtonSettings set = settings();
  const VecId x = VecId::position(), v = VecId::velocity(), f = VecId::force();
  const VecId du = mop.allocDeriv(), total = mop.allocDeriv(), trial = mop.allocDeriv();
  const VecId start = mop.allocCoord();
  const bool log = d_printLog.value() || (l_newtonSolver && l_newtonSolver->d_printLog.value());
  setStatus("Running");

  // Static: no velocity. The imposed positions of the end of the step (moving constraints)
  // are part of this step's equilibrium: in place before the first residual.
  mop.vOp(v, VecId::null(), VecId::null(), 0.0);
  mop.projectPosition(x);
  double normR = residual(mop, dt, f);
  const double normR0 = normR;
  bool converged = set.absoluteResidual > 0 && normR <= set.absoluteResidual;
  if (converged) setStatus("ConvergedEquilibrium");
  bool stalled = false, lineSearchFailed = false;
  int iteration = 0;
  // The matrix -K, assembled or applied by the linear solver at the current x.
  MechanicalParams stiffness;
  stiffness.dt = dt;
  stiffness.mFactor = 0.0;
  stiffness.kFactor = -1.0;

  while (!converged && iteration < set.iterations) {
    ++iteration;
    // Newton direction: -K du = R.
    mop.vOp(du, VecId::null(), VecId::null(), 0.0);
    const LinearSolveReport report = l_linearSolver->solve(mop, stiffness, du, f);
    if (!checkLinearSolve(mop, m_divergence, m_linear, report, *l_linearSolver.get(), m_step, du))
      return;
    mop.projectResponse(du);

    // Backtracking line search on |R(x + alpha du)|.
    mop.vOp(start, x);
    double alpha = 1.0, normTrial = 0.0;
    bool decreased = false;
    for (int trialIndex = 1;; ++trialIndex) {
      mop.vOp(x, start, du, alpha);
      normTrial = residual(mop, dt, trial);
      if (set.lineSearchTrials == 1 || normTrial <= (1.0 - 1e-4 * alpha) * normR) {
        decreased = true;
        break;
      }
      if (trialIndex >= set.lineSearchTrials) break;
      alpha *= set.lineSearchCoefficient;
    }
    lineSearchFailed = false;
    if (!decreased) {
      const bool roundoff = normR <= kRoundoff * normR0;
      if (!roundoff && set.warnWhenLineSearchFails && m_stalls++ == 0)
        msgWarning("the line search failed at step " + std::to_string(m_step) +
                       ", Newton iteration " + std::to_string(iteration) +
                       ": no step along the Newton direction reduces the residual |R| = " +
                       formatNumber(normR) + " N (smallest step tried: " + formatNumber(alpha) +
                       "); " +
                       (set.fullStepWhenLineSearchFails ? "the full step is taken"
                                                        : "the solver stays at the last point") +
                       ". The matrix may not be the derivative of the forces, or the load is "
                       "past a limit point; later failures are counted",
                   "maxNbIterationsLineSearch");
      lineSearchFailed = !roundoff;
      if (roundoff || set.fullStepWhenLineSearchFails) {
        // Round-off residual (no decrease to expect) or asked for: the full step.
        alpha = 1.0;
        mop.vOp(x, start, du, alpha);
        normTrial = residual(mop, dt, trial);
      } else if (normTrial >= normR) {
        // Stay at the last point; forces re-evaluated there for components that cache
        // per-evaluation data.
        mop.vOp(x, start);
        residual(mop, dt, f);
        stalled = true;
        break;
      }
    }
    const double previous = normR;
    mop.vOp(f, trial);
    normR = normTrial;
    mop.vOp(total, total, du, alpha);
    const double correction = alpha * mop.norm(du);
    const double displacement = mop.norm(total);
    if (log)
      msgInfo("step " + std::to_string(m_step) + ", Newton iteration " + std::to_string(iteration) +
              ": |R| = " + formatNumber(normR) + " N, |du| = " + formatNumber(correction) +
              " m, alpha = " + formatNumber(alpha));

    // Convergence criteria, in the order of SOFA's NewtonRaphsonSolver.
    const char* criterion = nullptr;
    if (set.relativeSuccessive > 0 && previous > 0 && normR / previous <= set.relativeSuccessive)
      criterion = "ConvergedResidualSuccessiveRatio";
    else if (set.relativeInitial > 0 && normR0 > 0 && normR / normR0 <= set.relativeInitial)
      criterion = "ConvergedResidualInitialRatio";
    else if (set.absoluteResidual > 0 && normR <= set.absoluteResidual)
      criterion = "ConvergedAbsoluteResidual";
    else if (set.relativeCorrection > 0 && displacement > 0 &&
             correction / displacement <= set.relativeCorrection)
      criterion = "ConvergedRelativeEstimateDifference";
    else if (set.absoluteCorrection > 0 && correction <= set.absoluteCorrection)
      criterion = "ConvergedAbsoluteEstimateDifference";
    if (criterion) {
      converged = true;
      setStatus(criterion);
      break;
    }
    if (set.stopWhenResidualGrows && normR > previous) {
      if (log)
        msgInfo("the residual grew: iterations stopped", "should_diverge_when_residual_is_growing");
      break;
    }
  }

  d_lastIterations.setValue(iteration);
  d_lastResidual.setValue(normR);
  d_lastConverged.setValue(converged);
  if (!converged) setStatus(lineSearchFailed ? "DivergedLineSearch" : "DivergedMaxIterations");
  if (log)
    msgInfo("step " + std::to_string(m_step) + ": " + (converged ? "converged" : "not converged") +
            " after " + std::to_string(iteration) + " Newton iteration(s), |R| = " +
            formatNumber(normR) + " N (|R_0| = " + formatNumber(normR0) + " N)");
  if (!converged && !stalled && set.warnWhenNotConverged && m_unconverged++ == 0)
    msgWarning("Newton did not converge in " + std::to_string(iteration) + " iterations at step " +
                   std::to_string(m_step) + ": |R| = " + formatNumber(normR) +
                   " N, |R_0| = " + formatNumber(normR0) +
                   " N (raise the iterations, or loosen the thresholds); later ones are "
                   "counted",
               l_newtonSolver ? "newtonSolver" : "newton_iterations");
  // A stall (f holds the residual at the current point).
  const bool noProgress = set.iterations > 1 && !converged && !(normR < normR0);
  if (stalled || noProgress) {
    const std::string reason =
        stalled ? "no step along the Newton direction lowers the residual |R| = " +
                      formatNumber(normR) + " N (Newton iteration " + std::to_string(iteration) +
                      "; the load may be past a limit point, or the tangent is not the forces' "
                      "derivative)"
                : "Newton ended after " + std::to_string(iteration) +
                      " iterations with |R| = " + formatNumber(normR) +
                      " N, not below |R_0| = " + formatNumber(normR0) +
                      " N (smaller load increments: more time steps)";
    if (!m_divergence.report(mop, DivergenceKind::newtonStall, m_step, reason,
                             mop.describeWorstVertex(f, "residual force"),
                             stalled ? "maxNbIterationsLineSearch" : "newton_iterations"))
      return;
  }
  mop.projectPosition(x);
  mop.vOp(v, VecId::null(), VecId::null(), 0.0);
  finishStep(mop, *this, m_step, m_divergence);
}

void StaticSolver::cleanup() {
  m_divergence.summarize(m_step);
  const char* field = l_newtonSolver ? "newtonSolver" : "newton_iterations";
  if (m_stalls > 1)
    msgWarning("the line search failed in " + std::to_string(m_stalls) +
                   " Newton iterations over " + std::to_string(m_step) + " steps",
               "maxNbIterationsLineSearch");
  if (m_unconverged > 1)
    msgWarning("Newton did not converge in " + std::to_string(m_unconverged) + " of " +
                   std::to_string(m_step) + " steps",
               field);
}

bool StaticSolver::constraintResponse(double dt, ConstraintResponse& response) const {
  // Equilibrium f(x + dx) + f_c = 0: -K dx = f_c; no velocity.
  response.matrix = MechanicalParams{};
  response.matrix.dt = dt;
  response.matrix.mFactor = 0.0;
  response.matrix.kFactor = -1.0;
  response.positionFactor = 1.0;
  response.velocityFactor = 0.0;
  return true;
}

}  // namespace stroma
