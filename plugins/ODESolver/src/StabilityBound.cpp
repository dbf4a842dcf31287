// SPDX-License-Identifier: MIT
#include "StabilityBound.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "simulation/Mass.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

double largestFrequency(MechanicalOperations& mop, int iterations, std::string* where) {
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
    if (where) *where = mop.describeWorstVertex(v, "highest mode");
  }
  mop.freeVec(a);
  mop.freeVec(kv);
  mop.freeVec(v);
  return std::sqrt(omega2);
}

bool ExplicitStabilityCheck::check(MechanicalOperations& mop, double dt, DivergenceMonitor& monitor,
                                   long long step) {
  const bool estimated = dt != m_checkedDt;
  if (estimated) {
    m_checkedDt = dt;
    const double omega = largestFrequency(mop, 60, &m_where);
    m_bound = omega > 0 ? m_constant / omega : 0.0;
    d_criticalTimeStep.setValue(m_bound);
    m_aboveBound = m_bound > 0 && dt > m_bound;
    if (m_aboveBound) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "dt = %.4g s is above the stability bound of %s, %.4g s (= %.4g / omega_max, "
                    "omega_max = %.4g rad/s the largest natural frequency of the scene); the run "
                    "will diverge unless damping or the nonlinearity saves it: lower dt below "
                    "%.4g s, or use EulerImplicitSolver",
                    dt, m_scheme, m_bound, m_constant, omega, m_bound);
      m_text = text;
    }
  }
  if (!m_aboveBound) return true;
  // Refused at every step while dt stays above the bound (each step fails), or warned once.
  if (monitor.stops())
    return monitor.report(mop, DivergenceKind::stabilityBound, step,
                          m_text + "; refused before integrating", m_where, "dt");
  if (estimated) m_solver.msgWarning(m_text);
  return true;
}

}  // namespace stroma
