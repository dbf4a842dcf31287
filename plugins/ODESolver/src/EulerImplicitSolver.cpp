// SPDX-License-Identifier: MIT
#include "EulerImplicitSolver.h"

#include <cmath>

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

void EulerImplicitSolver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState()) return;
  const double h = dt;
  const double rm = d_rayleighMass.value(), rs = d_rayleighStiffness.value();
  const double tr = 1.0;  // backward Euler
  const VecId x = VecId::position(), v = VecId::velocity(), f = VecId::force();
  const VecId b = mop.allocDeriv(), dv = mop.allocDeriv(), tmp = mop.allocDeriv();

  // Right-hand side: b = h [f + (h + rs) K v - rm M v]  (first order: b = h f).
  MechanicalParams mp;
  mp.dt = h;
  mop.computeForce(mp, f);
  mop.vOp(b, VecId::null(), f, h);
  if (!d_firstOrder.value()) {
    MechanicalParams damping;
    damping.mFactor = -rm;
    damping.kFactor = tr * h + rs;
    mop.computeMBKdx(damping, tmp, v);
    mop.vOp(b, b, tmp, h);
  }
  mop.projectResponse(b);

  // Matrix: (1 + h rm) M - h (tr h + rs) K   (first order: M - h K).
  MechanicalParams matrix;
  matrix.dt = h;
  matrix.mFactor = d_firstOrder.value() ? 1.0 : 1.0 + tr * h * rm;
  matrix.kFactor = d_firstOrder.value() ? -h * tr : -h * (tr * h + rs);
  matrix.bFactor = 0;
  mop.vOp(dv, VecId::null(), VecId::null(), 0.0);
  l_linearSolver->solve(mop, matrix, dv, b);

  // Integration.
  if (d_firstOrder.value()) {
    mop.vOp(v, VecId::null(), dv, 1.0 / h);
    mop.vOp(x, x, dv, 1.0);
  } else {
    mop.vOp(v, v, dv, 1.0);
    mop.vOp(x, x, v, h);
  }
  if (d_vdamping.value() > 0) mop.vOp(v, VecId::null(), v, std::exp(-h * d_vdamping.value()));
  mop.projectPosition(x);
  mop.projectVelocity(v);
  if (mop.checkFinite(x, "position", *this)) mop.checkFinite(v, "velocity", *this);
  mop.propagate(x, v);
}

}  // namespace stroma
