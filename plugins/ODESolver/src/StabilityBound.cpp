// SPDX-License-Identifier: MIT
#include "StabilityBound.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "simulation/Mass.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

double largestFrequency(MechanicalOperations& mop, int iterations) {
  const auto& masses = mop.masses();
  if (masses.empty() ||
      !std::all_of(masses.begin(), masses.end(), [](const BaseMass* m) { return m->isDiagonal(); }))
    return 0;
  // A fixed pseudo-random start (the same estimate every run), without the fixed points.
  Eigen::VectorXd start(static_cast<Eigen::Index>(mop.systemSize()));
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (Eigen::Index i = 0; i < start.size(); ++i) start[i] = uniform(random);
  const VecId v = mop.allocDeriv(), kv = mop.allocDeriv(), a = mop.allocDeriv();
  mop.scatter(start, v);
  mop.projectResponse(v);

  MechanicalParams stiffness;  // kv = -K v (K = df/dx is negative semi-definite)
  stiffness.mFactor = 0;
  stiffness.kFactor = -1;
  MechanicalParams mass;  // kv = M v
  mass.mFactor = 1;
  mass.kFactor = 0;
  double omega2 = 0;
  for (int i = 0; i < iterations; ++i) {
    const double length = mop.norm(v);
    if (!(length > 0) || !std::isfinite(length)) break;
    mop.vOp(v, VecId::null(), v, 1.0 / length);
    mop.computeMBKdx(stiffness, kv, v);
    mop.projectResponse(kv);
    if (!mop.accFromF(a, kv)) break;  // a = M^-1 (-K) v
    mop.projectResponse(a);
    mop.vOp(v, a);
  }
  // Rayleigh quotient of the last iterate: v.(-K v) / v.(M v), exact to the square of the
  // iterate's error for this symmetric pencil.
  const double length = mop.norm(v);
  if (length > 0 && std::isfinite(length)) {
    mop.computeMBKdx(stiffness, kv, v);
    mop.projectResponse(kv);
    const double vKv = mop.dot(v, kv);
    mop.computeMBKdx(mass, a, v);
    mop.projectResponse(a);
    const double vMv = mop.dot(v, a);
    if (vMv > 0 && vKv > 0) omega2 = vKv / vMv;
  }
  mop.freeVec(a);
  mop.freeVec(kv);
  mop.freeVec(v);
  return std::sqrt(omega2);
}

void ExplicitStabilityCheck::check(MechanicalOperations& mop, double dt) {
  if (dt == m_checkedDt) return;
  m_checkedDt = dt;
  const double omega = largestFrequency(mop);
  const double bound = omega > 0 ? m_constant / omega : 0.0;
  d_criticalTimeStep.setValue(bound);
  if (!(bound > 0) || dt <= bound) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "dt = %.4g s is above the stability bound of %s, %.4g s (= %.4g / omega_max, "
                "omega_max = %.4g rad/s the largest natural frequency of the scene); the run will "
                "diverge unless damping or the nonlinearity saves it: lower dt below %.4g s, or "
                "use EulerImplicitSolver",
                dt, m_scheme, bound, m_constant, omega, bound);
  m_solver.msgWarning(text);
}

}  // namespace stroma
