// SPDX-License-Identifier: MIT
// Checks shared by every time integrator: a usable time step before the step, finite positions
// and velocities after it, the divergence checks of DivergenceMonitor.h; and the stage
// acceleration of the explicit Runge-Kutta schemes. Free functions rather than a base class
// (STYLE.md section 4).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "DivergenceMonitor.h"
#include "core/Base.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

/// Reports a time step that is not a positive finite number as an error of `solver` (which
/// stops the run with exit code 1) and returns false.
inline bool checkTimeStep(Base& solver, double dt) {
  if (dt > 0 && std::isfinite(dt)) return true;
  char value[32];
  std::snprintf(value, sizeof value, "%g", dt);
  solver.msgError("the time step dt = " + std::string(value) +
                      " s is not positive: set a positive dt on the root node or on this "
                      "solver's node",
                  "dt");
  return false;
}

/// After a step: reports non-finite positions or velocities (naming the solver's step number,
/// the time, the state and the index) and returns false; otherwise propagates the new state
/// to the mapped states, feeds the energy-growth check when there is one (dynamic solvers)
/// and returns false only when that reports a divergence that stops the run.
inline bool finishStep(MechanicalOperations& mop, Base& solver, long long step,
                       DivergenceMonitor& monitor, EnergyGrowthCheck* energy = nullptr) {
  const VecId x = VecId::position(), v = VecId::velocity();
  // The message is written only for a state that is not finite: a warm step allocates nothing.
  const auto finite = [&](VecId id, const char* what) {
    return std::isfinite(mop.worstVertex(id).value) ||
           mop.checkFinite(id, std::string(what) + " after step " + std::to_string(step), solver);
  };
  if (!finite(x, "position") || !finite(v, "velocity")) return false;
  mop.propagate(x, v);
  std::string reason;
  if (energy && energy->grew(mop, reason))
    return monitor.report(mop, DivergenceKind::energyGrowth, step, reason,
                          mop.describeWorstVertex(v, "velocity"), "energyGrowth");
  return true;
}

/// After a linear solve whose solution is `solution`: reports it as a divergence when `check`
/// says so. Returns false when the run stops.
inline bool checkLinearSolve(MechanicalOperations& mop, DivergenceMonitor& monitor,
                             const LinearSolveCheck& check, const LinearSolveReport& report,
                             const Base& linearSolver, long long step, VecId solution) {
  std::string reason;
  if (!check.diverged(report, linearSolver, reason)) return true;
  return monitor.report(mop, DivergenceKind::linearSolve, step, reason,
                        mop.describeWorstVertex(solution, "solution"), "maxLinearResidual");
}

/// a = M^-1 f(x, v) at a stage state of an explicit scheme (RungeKutta2Solver,
/// RungeKutta4Solver), mapped states updated first. False when a mass cannot invert (reported).
inline bool stageAcceleration(MechanicalOperations& mop, double h, VecId x, VecId v, VecId a) {
  mop.propagate(x, v);
  MechanicalParams mp;
  mp.dt = h;
  mp.x = x;
  mp.v = v;
  mop.computeForce(mp, VecId::force());
  if (!mop.accFromF(a, VecId::force())) return false;
  mop.projectResponse(a);
  return true;
}

}  // namespace stroma
