// SPDX-License-Identifier: MIT
#include "RungeKutta4Solver.h"

#include "StepChecks.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

void RungeKutta4Solver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState() || !checkTimeStep(*this, dt)) return;
  ++m_step;
  const double h = dt;
  const VecId x = VecId::position(), v = VecId::velocity();
  const VecId xs = mop.allocCoord(), vs = mop.allocDeriv(), a = mop.allocDeriv();
  const VecId sumV = mop.allocDeriv(), sumA = mop.allocDeriv();

  // k1 = (v_n, a(x_n, v_n)).
  if (!stageAcceleration(mop, h, x, v, a)) return;
  if (!m_stability.check(mop, h, m_divergence, m_step)) return;  // linearized at (x_n, v_n)
  mop.vOp(sumV, v);
  mop.vOp(sumA, a);
  mop.vOp(xs, x, v, h / 2);
  mop.vOp(vs, v, a, h / 2);
  // k2 and k3 at the half step, weights 2; stage states y_n + c h k.
  for (const double c : {0.5, 1.0}) {
    if (!stageAcceleration(mop, h, xs, vs, a)) return;
    mop.vOp(sumV, sumV, vs, 2.0);
    mop.vOp(sumA, sumA, a, 2.0);
    mop.vOp(xs, x, vs, c * h);  // uses this stage's velocity before it is replaced
    mop.vOp(vs, v, a, c * h);
  }
  // k4 at the full step.
  if (!stageAcceleration(mop, h, xs, vs, a)) return;
  mop.vOp(sumV, sumV, vs);
  mop.vOp(sumA, sumA, a);

  mop.vOp(x, x, sumV, h / 6);
  mop.vOp(v, v, sumA, h / 6);
  mop.projectPosition(x);
  mop.projectVelocity(v);
  finishStep(mop, *this, m_step, m_divergence, &m_energy);
}

}  // namespace stroma
