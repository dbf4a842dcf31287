// SPDX-License-Identifier: MIT
#include "EulerExplicitSolver.h"

#include "simulation/MechanicalOperations.h"

namespace stroma {

void EulerExplicitSolver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState()) return;
  const VecId x = VecId::position(), v = VecId::velocity(), f = VecId::force();
  MechanicalParams mp;
  mp.dt = dt;
  mop.computeForce(mp, f);
  const VecId a = mop.allocDeriv();
  if (!mop.accFromF(a, f)) return;
  mop.projectResponse(a);
  if (d_symplectic.value()) {
    mop.vOp(v, v, a, dt);  // v += h a
    mop.vOp(x, x, v, dt);  // x += h v_{n+1}
  } else {
    mop.vOp(x, x, v, dt);  // x += h v_n
    mop.vOp(v, v, a, dt);
  }
  mop.projectPosition(x);
  mop.projectVelocity(v);
  if (mop.checkFinite(x, "position", *this)) mop.checkFinite(v, "velocity", *this);
  mop.propagate(x, v);
}

}  // namespace stroma
