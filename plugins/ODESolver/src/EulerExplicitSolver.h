// SPDX-License-Identifier: MIT
#pragma once

#include "DivergenceMonitor.h"
#include "StabilityBound.h"
#include "core/Link.h"
#include "simulation/Constraints.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Explicit Euler (SOFA's EulerExplicitSolver). With symplectic="true" (the default), the
/// semi-implicit (symplectic) Euler scheme:
///   a = M^-1 f(x_n, v_n),  v_{n+1} = v_n + h a,  x_{n+1} = x_n + h v_{n+1};
/// otherwise forward Euler, x_{n+1} = x_n + h v_n. With lumped masses M^-1 f is a division per
/// degree of freedom; with a non-diagonal mass (MeshMatrixMass without lumping) M a = f is
/// solved by the node's linear solver. Symplectic Euler is stable only below 2 / omega_max (the
/// Courant time step of the stiffest element): estimated at the first step with lumped
/// masses (output `criticalTimeStep`), and a larger dt is warned about.
class EulerExplicitSolver final : public OdeSolver {
 public:
  Data<bool> d_symplectic{this, "symplectic", true,
                          "Semi-implicit (symplectic) Euler: positions use the new velocities."};
  Data<bool> d_optimizedForDiagonalMatrix{this, "optimizedForDiagonalMatrix", true,
                                          "SOFA option, accepted: lumped masses are inverted "
                                          "directly, other masses through the linear solver."};
  Data<bool> d_threadSafeVisitor{this, "threadSafeVisitor", false,
                                 "SOFA option, accepted and without effect."};
  Link<LinearSolver> l_linearSolver{this, "linearSolver",
                                    "Linear solver for a non-diagonal mass (default: the "
                                    "node's, when there is one)."};

  void init() override;
  void solve(MechanicalOperations& mop, double dt) override;
  bool constraintResponse(double dt, ConstraintResponse& response) const override;
  void cleanup() override { m_divergence.summarize(m_step); }

 private:
  long long m_step = 0;
  DivergenceMonitor m_divergence{*this};
  EnergyGrowthCheck m_energy{*this};
  LinearSolveCheck m_linear{*this};

 public:
  ExplicitStabilityCheck m_stability{*this, 2.0, "symplectic Euler"};
};

}  // namespace stroma
