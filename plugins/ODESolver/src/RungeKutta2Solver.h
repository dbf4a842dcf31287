// SPDX-License-Identifier: MIT
#pragma once

#include "DivergenceMonitor.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Explicit midpoint rule, a second-order Runge-Kutta scheme (SOFA's RungeKutta2Solver), on
/// x' = v, v' = M^-1 f(x, v) with lumped masses (Hairer, Norsett and Wanner 1993, "Solving
/// Ordinary Differential Equations I", section II.1, eq. 1.6):
///   y_mid = y_n + h/2 F(y_n),   y_{n+1} = y_n + h F(y_mid),   y = (x, v).
/// Two force evaluations per step; the global error is O(h^2). On an undamped oscillator the
/// amplification per step is sqrt(1 + (omega h)^4 / 4) > 1: the energy grows slowly at any
/// step (no stability bound to check), which the energy-growth check watches.
class RungeKutta2Solver final : public OdeSolver {
 public:
  void solve(MechanicalOperations& mop, double dt) override;
  void cleanup() override { m_divergence.summarize(m_step); }

 private:
  long long m_step = 0;
  DivergenceMonitor m_divergence{*this};
  EnergyGrowthCheck m_energy{*this};
};

}  // namespace stroma
