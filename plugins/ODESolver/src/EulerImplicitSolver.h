// SPDX-License-Identifier: MIT
#pragma once

#include "DivergenceMonitor.h"
#include "core/Link.h"
#include "simulation/Constraints.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Implicit (backward) Euler, SOFA's EulerImplicitSolver, with Rayleigh damping
/// B = -(rayleighMass M - rayleighStiffness K) (K = df/dx, negative semi-definite).
///
/// By default (newtonIterations = 1) the step is linearized once (Baraff and Witkin 1998,
/// eq. 6 with the damping terms):
///   [(1 + h rm) M - h (h + rs) K] dv = h [f(x_n, v_n) + (h + rs) K v_n - rm M v_n]
///   v_{n+1} = v_n + dv,  x_{n+1} = x_n + h v_{n+1}.
/// With newtonIterations > 1 (a Stroma option; SOFA has none), the nonlinear equation
///   r(v) = h [f(x_n + h v, v) - rm M v + rs K v] - M (v - v_n) = 0
/// is then solved by Newton iterations that reuse the same matrix, re-evaluated at each
/// iterate, until ||r|| <= newtonTolerance ||r_0|| (r_0: the right-hand side of the first
/// iteration). firstOrder solves M v = f(x_n + h v) instead, the quasi-static first-order
/// system, with M - h K.
///
/// Reports: dt <= 0, a missing linear solver, non-finite results (the run stops with exit
/// code 1); a warning the first time Newton stops unconverged, the count at the end of the run.
/// Divergences (DivergenceMonitor.h, after onDivergence): kinetic energy growth, a linear solve
/// stopped above maxLinearResidual, and a stalled Newton iteration: unconverged with a last
/// iteration that did not lower the residual, or a final residual not below the first one.
class EulerImplicitSolver final : public OdeSolver {
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
  Data<double> d_vdamping{
      this, "vdamping", 0.0, "Velocity decay per second (0: none).", {.unit = "1/s", .min = 0.0}};
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
  Data<bool> d_computeResidual{
      this, "computeResidual", false,
      "Evaluate the residual of the nonlinear equation after each step "
      "(one more force evaluation) into lastResidual; logged with printLog."};
  Data<int> d_newtonIterations{this,
                               "newtonIterations",
                               1,
                               "Linear solves per step: 1 is the linearized step; more iterate "
                               "Newton on the nonlinear implicit equation (Stroma option).",
                               {.min = 1.0, .max = 1000.0}};
  Data<double> d_newtonTolerance{this,
                                 "newtonTolerance",
                                 1e-6,
                                 "Newton stops when the residual norm falls below this fraction "
                                 "of the first right-hand side's norm.",
                                 {.min = 0.0}};
  Data<int> d_lastIterations{
      this, "lastIterations", 0, "Linear solves of the last step.", {.output = true}};
  Data<double> d_lastResidual{this,
                              "lastResidual",
                              0.0,
                              "Relative residual ||r|| / ||r_0|| after the last step (when "
                              "newtonIterations > 1 or computeResidual).",
                              {.output = true}};
  Link<LinearSolver> l_linearSolver{this, "linearSolver", "Linear solver (default: the node's)."};

  void init() override;
  void solve(MechanicalOperations& mop, double dt) override;
  bool constraintResponse(double dt, ConstraintResponse& response) const override;
  void cleanup() override;

 private:
  /// r = h [f(x, v) - rm M v + rs K v] - M (v - v_n) (second order), or
  /// r = h f(x) - M (x - x_n) (first order), at the current position and velocity, projected.
  /// `mvn` holds M v_n. Evaluates the forces, so K is then the one at the current state.
  void computeResidual(MechanicalOperations& mop, double h, VecId r, VecId mvn);

  long long m_step = 0;
  long long m_unconverged = 0;
  DivergenceMonitor m_divergence{*this};
  EnergyGrowthCheck m_energy{*this};
  LinearSolveCheck m_linear{*this};
};

}  // namespace stroma
