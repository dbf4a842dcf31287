// SPDX-License-Identifier: MIT
#include "EulerExplicitSolver.h"

#include <algorithm>

#include "StepChecks.h"
#include "core/Node.h"
#include "simulation/Mass.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

void EulerExplicitSolver::init() {
  if (!l_linearSolver && node()) l_linearSolver.set(node()->get<LinearSolver>());
}

void EulerExplicitSolver::solve(MechanicalOperations& mop, double dt) {
  if (!mop.hasState() || !checkTimeStep(*this, dt)) return;
  ++m_step;
  const VecId x = VecId::position(), v = VecId::velocity(), f = VecId::force();
  MechanicalParams mp;
  mp.dt = dt;
  mop.computeForce(mp, f);
  if (d_symplectic.value() && !m_stability.check(mop, dt, m_divergence, m_step)) return;
  const VecId a = mop.allocDeriv();

  // a = M^-1 f: a division for lumped masses, a linear solve otherwise.
  const auto& masses = mop.masses();
  const bool lumped =
      std::all_of(masses.begin(), masses.end(), [](const BaseMass* m) { return m->isDiagonal(); });
  if (lumped || !l_linearSolver) {
    if (!mop.accFromF(a, f)) return;
  } else {
    mop.projectResponse(f);
    MechanicalParams massOnly;
    massOnly.dt = dt;
    massOnly.mFactor = 1.0;
    massOnly.kFactor = 0.0;
    const LinearSolveReport report = l_linearSolver->solve(mop, massOnly, a, f);
    if (!checkLinearSolve(mop, m_divergence, m_linear, report, *l_linearSolver.get(), m_step, a))
      return;
  }
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
  finishStep(mop, *this, m_step, m_divergence, &m_energy);
}

bool EulerExplicitSolver::constraintResponse(double dt, ConstraintResponse& response) const {
  // Symplectic Euler: dv = h M^-1 f, x moves by h dv. Forward Euler moves x with the old
  // velocity: a force of the step does not move it, so no constraint can act on it.
  if (!d_symplectic.value()) return false;
  response.matrix = MechanicalParams{};
  response.matrix.dt = dt;
  response.matrix.mFactor = 1.0;
  response.matrix.kFactor = 0.0;
  response.positionFactor = dt * dt;
  response.velocityFactor = dt;
  return true;
}

}  // namespace stroma
