// SPDX-License-Identifier: MIT
#include "NewmarkImplicitSolver.h"

#include <algorithm>

#include "StepChecks.h"
#include "core/Node.h"
#include "simulation/Mass.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

void NewmarkImplicitSolver::init() {
  if (!l_linearSolver && node()) l_linearSolver.set(node()->get<LinearSolver>());
  if (!l_linearSolver)
    msgError("needs a linear solver in its node (CGLinearSolver, SparseLDLSolver, ...)",
             "linearSolver");
  if (d_gamma.value() < 0.5 || 2 * d_beta.value() < d_gamma.value())
    msgWarning("gamma = " + std::to_string(d_gamma.value()) +
                   ", beta = " + std::to_string(d_beta.value()) +
                   " is only conditionally stable (unconditional for 2 beta >= gamma >= 1/2)",
               "beta");
}

void NewmarkImplicitSolver::initialAcceleration(MechanicalOperations& mop, double h, VecId a) {
  const VecId v = VecId::velocity();
  const VecId rhs = mop.allocDeriv();
  // rhs = f_0 - rm M v_0 + rs K v_0
  MechanicalParams damping;
  damping.dt = h;
  damping.mFactor = -d_rayleighMass.value();
  damping.kFactor = d_rayleighStiffness.value();
  mop.computeMBKdx(damping, rhs, v);
  mop.vOp(rhs, rhs, VecId::force(), 1.0);
  mop.projectResponse(rhs);
  const auto& masses = mop.masses();
  if (std::all_of(masses.begin(), masses.end(),
                  [](const BaseMass* m) { return m->isDiagonal(); })) {
    mop.accFromF(a, rhs);
  } else {
    MechanicalParams massOnly;
    massOnly.dt = h;
    massOnly.mFactor = 1.0;
    massOnly.kFactor = 0.0;
    l_linearSolver->solve(mop, massOnly, a, rhs);
  }
  mop.projectResponse(a);
  mop.freeVec(rhs);
}

void NewmarkImplicitSolver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState() || !checkTimeStep(*this, dt)) return;
  ++m_step;
  const double h = dt, rm = d_rayleighMass.value(), rs = d_rayleighStiffness.value();
  const double gamma = d_gamma.value(), beta = d_beta.value();
  const VecId x = VecId::position(), v = VecId::velocity(), f = VecId::force();
  const VecId an = mop.allocDeriv(), a1 = mop.allocDeriv();
  const VecId w = mop.allocDeriv(), tmp = mop.allocDeriv(), b = mop.allocDeriv();

  // f_n, and a_n (kept from the last step, or computed at the first).
  MechanicalParams mp;
  mp.dt = h;
  mop.computeForce(mp, f);
  if (m_hasAcceleration && m_acceleration.size() == static_cast<Eigen::Index>(mop.systemSize()))
    mop.scatter(m_acceleration, an);
  else
    initialAcceleration(mop, h, an);

  // b = f_n + K [(h + rs) v_n + (h^2 (1/2 - beta) + h rs (1 - gamma)) a_n]
  //         - rm M [v_n + h (1 - gamma) a_n]
  MechanicalParams stiffness;
  stiffness.dt = h;
  stiffness.kFactor = 1.0;
  mop.vOp(w, VecId::null(), v, h + rs);
  mop.vOp(w, w, an, h * h * (0.5 - beta) + h * rs * (1 - gamma));
  mop.computeMBKdx(stiffness, tmp, w);
  mop.vOp(b, f, tmp, 1.0);
  if (rm != 0) {
    MechanicalParams mass;
    mass.dt = h;
    mass.mFactor = -rm;
    mass.kFactor = 0.0;
    mop.vOp(w, v, an, h * (1 - gamma));
    mop.computeMBKdx(mass, tmp, w);
    mop.vOp(b, b, tmp, 1.0);
  }
  mop.projectResponse(b);

  // [(1 + h gamma rm) M - (h^2 beta + h gamma rs) K] a_{n+1} = b
  MechanicalParams matrix;
  matrix.dt = h;
  matrix.mFactor = 1.0 + h * gamma * rm;
  matrix.kFactor = -(h * h * beta + h * gamma * rs);
  const LinearSolveReport report = l_linearSolver->solve(mop, matrix, a1, b);
  if (!checkLinearSolve(mop, m_divergence, m_linear, report, *l_linearSolver.get(), m_step, a1))
    return;
  mop.projectResponse(a1);

  // Newmark updates: x first (it uses v_n).
  mop.vOp(x, x, v, h);
  mop.vOp(x, x, an, h * h * (0.5 - beta));
  mop.vOp(x, x, a1, h * h * beta);
  mop.vOp(v, v, an, h * (1 - gamma));
  mop.vOp(v, v, a1, h * gamma);
  mop.projectPosition(x);
  mop.projectVelocity(v);
  mop.gather(a1, m_acceleration);
  m_hasAcceleration = true;
  finishStep(mop, *this, m_step, m_divergence, &m_energy);
}

}  // namespace stroma
