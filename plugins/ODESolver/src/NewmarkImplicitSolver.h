// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include "DivergenceMonitor.h"
#include "core/Link.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Newmark's beta method (Newmark 1959, "A method of computation for structural dynamics",
/// J. Eng. Mech. Div. ASCE 85, eqs. 3 and 4), SOFA's NewmarkImplicitSolver:
///   x_{n+1} = x_n + h v_n + h^2 [(1/2 - beta) a_n + beta a_{n+1}]
///   v_{n+1} = v_n + h [(1 - gamma) a_n + gamma a_{n+1}]
///   M a_{n+1} = f(x_{n+1}) - C v_{n+1},   C = rayleighMass M - rayleighStiffness K,
/// with f linearized about x_n (K = df/dx), which gives for a_{n+1}
///   [(1 + h gamma rm) M - (h^2 beta + h gamma rs) K] a_{n+1}
///       = f_n + K [(h + rs) v_n + (h^2 (1/2 - beta) + h rs (1 - gamma)) a_n]
///         - rm M [v_n + h (1 - gamma) a_n].
/// The acceleration is kept between steps (a_0 from M a_0 = f_0 - C v_0 at the first step, or
/// when the system changes size). gamma = 1/2, beta = 1/4 (average acceleration, the default)
/// is second-order accurate, unconditionally stable and keeps the energy of an undamped linear
/// system exactly; 2 beta >= gamma >= 1/2 is unconditionally stable.
class NewmarkImplicitSolver final : public OdeSolver {
 public:
  Data<double> d_rayleighStiffness{this,
                                   "rayleighStiffness",
                                   0.0,
                                   "Rayleigh damping proportional to the stiffness.",
                                   {.unit = "s", .min = 0.0}};
  Data<double> d_rayleighMass{this,
                              "rayleighMass",
                              0.0,
                              "Rayleigh damping proportional to the mass.",
                              {.unit = "1/s", .min = 0.0}};
  Data<double> d_gamma{this,
                       "gamma",
                       0.5,
                       "Newmark gamma: weight of the new acceleration in the velocity update.",
                       {.min = 0.0, .max = 1.0}};
  Data<double> d_beta{this,
                      "beta",
                      0.25,
                      "Newmark beta: weight of the new acceleration in the position update.",
                      {.min = 0.0, .max = 0.5}};
  Data<bool> d_threadSafeVisitor{this, "threadSafeVisitor", false,
                                 "SOFA option, accepted and without effect."};
  Link<LinearSolver> l_linearSolver{this, "linearSolver", "Linear solver (default: the node's)."};

  void init() override;
  void solve(MechanicalOperations& mop, double dt) override;
  void cleanup() override { m_divergence.summarize(m_step); }

 private:
  /// a_0 from M a_0 = f_0 - C v_0 (f_0 in the force vector, C v_0 added here).
  void initialAcceleration(MechanicalOperations& mop, double h, VecId a);

  Eigen::VectorXd m_acceleration;  ///< a_n of the independent states, between steps
  bool m_hasAcceleration = false;
  long long m_step = 0;
  DivergenceMonitor m_divergence{*this};
  EnergyGrowthCheck m_energy{*this};
  LinearSolveCheck m_linear{*this};
};

}  // namespace stroma
