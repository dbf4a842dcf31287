// SPDX-License-Identifier: MIT
#include "CentralDifferenceSolver.h"

#include "StepChecks.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

void CentralDifferenceSolver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState() || !checkTimeStep(*this, dt)) return;
  ++m_step;
  const double h = dt, rm = d_rayleighMass.value();
  const VecId x = VecId::position(), v = VecId::velocity(), f = VecId::force();
  MechanicalParams mp;
  mp.dt = h;
  mop.computeForce(mp, f);
  if (!m_stability.check(mop, h, m_divergence, m_step)) return;
  const VecId a = mop.allocDeriv();
  if (!mop.accFromF(a, f)) return;
  mop.projectResponse(a);

  // Seed 000 eq. 3.3 divided by m/h: v_{n+1/2} = [(1/h - rm/2) v_{n-1/2} + a] / (1/h + rm/2).
  const double denominator = 1.0 / h + 0.5 * rm;
  mop.vOp(v, VecId::null(), v, (1.0 / h - 0.5 * rm) / denominator);
  mop.vOp(v, v, a, 1.0 / denominator);
  mop.vOp(x, x, v, h);
  mop.projectPosition(x);
  mop.projectVelocity(v);
  finishStep(mop, *this, m_step, m_divergence, &m_energy);
}

}  // namespace stroma
