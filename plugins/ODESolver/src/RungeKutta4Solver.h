// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

#include "DivergenceMonitor.h"
#include "StabilityBound.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Classic fourth-order Runge-Kutta (SOFA's RungeKutta4Solver) on the first-order system
/// x' = v, v' = M^-1 f(x, v), with lumped masses (Kutta 1901; Hairer, Norsett and Wanner
/// 1993, "Solving Ordinary Differential Equations I", section II.1):
///   k1 = F(y_n), k2 = F(y_n + h/2 k1), k3 = F(y_n + h/2 k2), k4 = F(y_n + h k3),
///   y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4),   y = (x, v).
/// Four force evaluations per step; the error is O(h^4). Explicit: stable for omega h below
/// 2 sqrt(2) on an undamped oscillator: the bound is estimated at the first step (output
/// `criticalTimeStep`) and a larger dt is warned about.
class RungeKutta4Solver final : public OdeSolver {
 public:
  void solve(MechanicalOperations& mop, double dt) override;
  void cleanup() override { m_divergence.summarize(m_step); }

 private:
  long long m_step = 0;
  DivergenceMonitor m_divergence{*this};
  EnergyGrowthCheck m_energy{*this};

 public:
  ExplicitStabilityCheck m_stability{*this, 2.0 * std::sqrt(2.0), "the classic Runge-Kutta scheme"};
};

}  // namespace stroma
