// SPDX-License-Identifier: MIT
#pragma once

#include "core/Link.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Implicit (backward) Euler, linearized once per step (Baraff and Witkin 1998), SOFA's
/// EulerImplicitSolver with Rayleigh damping B = -(rayleighMass M + rayleighStiffness K):
///   [(1 + h rm) M - h (h + rs) K] dv = h [f(x_n, v_n) + (h + rs) K v_n - rm M v_n]
///   v_{n+1} = v_n + dv,  x_{n+1} = x_n + h v_{n+1}
/// (K = df/dx). The linear system goes to the node's linear solver.
class EulerImplicitSolver final : public OdeSolver {
 public:
  Data<double> d_rayleighStiffness{this, "rayleighStiffness", 0.0,
                                   "Rayleigh damping proportional to the stiffness.",
                                   {.unit = "s", .min = 0.0}};
  Data<double> d_rayleighMass{this, "rayleighMass", 0.0,
                              "Rayleigh damping proportional to the mass.",
                              {.unit = "1/s", .min = 0.0}};
  Data<double> d_vdamping{this, "vdamping", 0.0,
                          "Velocity decay per second (0: none).", {.unit = "1/s", .min = 0.0}};
  Data<bool> d_firstOrder{this, "firstOrder", false,
                          "First-order system (velocities only, quasi-static)."};
  Data<bool> d_trapezoidalScheme{this, "trapezoidalScheme", false,
                                 "SOFA option, accepted: Stroma integrates with backward Euler "
                                 "(NewmarkImplicitSolver is the second-order scheme); a warning "
                                 "says so when set."};
  Data<bool> d_solveConstraint{this, "solveConstraint", false,
                               "SOFA option, accepted and without effect."};
  Data<bool> d_threadSafeVisitor{this, "threadSafeVisitor", false,
                                 "SOFA option, accepted and without effect."};
  Data<bool> d_computeResidual{this, "computeResidual", false,
                               "Report the residual of the nonlinear equation after the step."};
  Link<LinearSolver> l_linearSolver{this, "linearSolver",
                                    "Linear solver (default: the node's)."};

  void init() override;
  void solve(MechanicalOperations& mop, double dt) override;
};

}  // namespace stroma
