// SPDX-License-Identifier: MIT
#pragma once

#include "DivergenceMonitor.h"
#include "StabilityBound.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Explicit central differences with lumped masses and Rayleigh mass damping (SOFA's
/// CentralDifferenceSolver). The scheme of Cotin's mass-tensor model (seed 000, eq. 3.3),
///   (m/h^2 - g/(2h)) P_{n+1} = F_n + (2m/h^2) P_n - (m/h^2 + g/(2h)) P_{n-1},
/// for m P'' = g P' + F with the damping coefficient g = -rayleighMass m, written with the
/// half-step velocities v_{n+1/2} = (P_{n+1} - P_n) / h (leapfrog form, same iterates):
///   v_{n+1/2} = [(1/h - rm/2) v_{n-1/2} + M^-1 f(x_n, v_{n-1/2})] / (1/h + rm/2)
///   x_{n+1}   = x_n + h v_{n+1/2}.
/// The stored velocity is v_{n+1/2}; the initial one is taken as v_{-1/2}. Needs lumped masses.
/// Undamped, it keeps the energy of a linear system bounded for h < 2 / omega_max (Courant);
/// beyond, the run diverges and stops at the first non-finite value. The bound is estimated
/// at the first step (output `criticalTimeStep`) and a larger dt is warned about.
class CentralDifferenceSolver final : public OdeSolver {
 public:
  Data<double> d_rayleighMass{this,
                              "rayleighMass",
                              0.0,
                              "Rayleigh damping proportional to the mass.",
                              {.unit = "1/s", .min = 0.0}};
  Data<bool> d_threadSafeVisitor{this, "threadSafeVisitor", false,
                                 "SOFA option, accepted and without effect."};

  void solve(MechanicalOperations& mop, double dt) override;
  void cleanup() override { m_divergence.summarize(m_step); }

 private:
  long long m_step = 0;
  DivergenceMonitor m_divergence{*this};
  EnergyGrowthCheck m_energy{*this};

 public:
  ExplicitStabilityCheck m_stability{*this, 2.0, "central differences"};
};

}  // namespace stroma
