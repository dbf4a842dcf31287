// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "CGLinearSolver.h"
#include "EulerImplicitSolver.h"

namespace stroma {

/// SOFA's older CGImplicitSolver (alias CGImplicit): implicit Euler whose linear solve is a
/// matrix-free conjugate gradient of its own. SOFA itself now reads this element as an
/// EulerImplicitSolver followed by a CGLinearSolver; Stroma does the same inside one
/// component: it owns an EulerImplicitSolver (the step, with its Rayleigh damping, divergence
/// checks and constraint response) and a CGLinearSolver<GraphScattered> that the step uses,
/// whatever other linear solver the node holds. The owned objects follow this component's Data
/// and their messages are reported as this component's.
class CGImplicitSolver final : public OdeSolver {
 public:
  Data<int> d_iterations{this, "iterations", 25, "Maximum number of CG iterations per step.",
                         {.min = 1.0}};
  Data<double> d_tolerance{this, "tolerance", 1e-5,
                           "CG stops when the residual ||r|| / ||rhs|| falls below it.",
                           {.min = 0.0}};
  Data<double> d_threshold{this, "threshold", 1e-5,
                           "CG stops when a denominator (p.Ap) falls below it.", {.min = 0.0}};
  Data<double> d_rayleighStiffness{this,
                                   "rayleighStiffness",
                                   0.1,
                                   "Rayleigh damping proportional to the stiffness (0.1: the "
                                   "default of SOFA's CGImplicit, not EulerImplicitSolver's 0).",
                                   {.unit = "s", .min = 0.0}};
  Data<double> d_rayleighMass{this,
                              "rayleighMass",
                              0.1,
                              "Rayleigh damping proportional to the mass (0.1: the default of "
                              "SOFA's CGImplicit, not EulerImplicitSolver's 0).",
                              {.unit = "1/s", .min = 0.0}};
  Data<double> d_vdamping{
      this, "vdamping", 0.0, "Velocity decay per second (0: none).", {.unit = "1/s", .min = 0.0}};
  Data<bool> d_verbose{this, "verbose", false, "Report every CG solve."};

  CGImplicitSolver();

  void init() override;
  void solve(MechanicalOperations& mop, double dt) override;
  bool constraintResponse(double dt, ConstraintResponse& response) const override;
  void cleanup() override;

  /// CG iterations of the last step.
  int lastIterations() const { return m_cg.d_lastIterations.value(); }

 private:
  EulerImplicitSolver m_euler;
  CGLinearSolver m_cg;
};

}  // namespace stroma
