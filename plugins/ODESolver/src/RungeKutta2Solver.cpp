// SPDX-License-Identifier: MIT
#include "RungeKutta2Solver.h"

#include "StepChecks.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

void RungeKutta2Solver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState() || !checkTimeStep(*this, dt)) return;
  ++m_step;
  const double h = dt;
  const VecId x = VecId::position(), v = VecId::velocity();
  const VecId xm = mop.allocCoord(), vm = mop.allocDeriv(), a = mop.allocDeriv();

  // Midpoint state y_n + h/2 F(y_n).
  if (!stageAcceleration(mop, h, x, v, a)) return;
  mop.vOp(xm, x, v, h / 2);
  mop.vOp(vm, v, a, h / 2);
  // y_{n+1} = y_n + h F(y_mid).
  if (!stageAcceleration(mop, h, xm, vm, a)) return;
  mop.vOp(x, x, vm, h);
  mop.vOp(v, v, a, h);
  mop.projectPosition(x);
  mop.projectVelocity(v);
  finishStep(mop, *this, m_step, m_divergence, &m_energy);
}

}  // namespace stroma
