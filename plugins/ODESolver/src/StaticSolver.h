// SPDX-License-Identifier: MIT
#pragma once

#include "DivergenceMonitor.h"
#include "NewtonRaphsonSolver.h"
#include "NewtonSettings.h"
#include "core/Link.h"
#include "simulation/Constraints.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Static equilibrium f(x) = 0 by Newton-Raphson (SOFA's StaticSolver), one load increment per
/// time step. Each iteration solves -K du = f(x) (K = df/dx at x) with the node's linear
/// solver, then a backtracking line search on the residual norm takes the first of the step
/// lengths a = 1, c, c^2, ... (at most maxNbIterationsLineSearch of them, c = 1/2) with
///   ||f(x + a du)|| <= (1 - 1e-4 a) ||f(x)||
/// (Armijo's condition on 1/2 ||f||^2 along the Newton direction; Dennis and Schnabel 1996,
/// "Numerical Methods for Unconstrained Optimization and Nonlinear Equations", section 6.3).
/// When no trial decreases the residual the solver stalls: it stays at the last point and
/// stops. The iterations stop at the first criterion met (a threshold <= 0 disables it):
/// |a du| <= absolute_correction_tolerance_threshold, |a du| / |U| <=
/// relative_correction_tolerance_threshold (U: the displacement of this step so far),
/// |R| <= absolute_residual_tolerance_threshold, |R| / |R_0| <=
/// relative_residual_tolerance_threshold. Velocities are set to zero.
///
/// With `newtonSolver` linking a NewtonRaphsonSolver (SOFA's newer form), the parameters are
/// that component's instead, and its `status` tells the outcome.
///
/// Reports: with printLog, each iteration (|R|, |du|, a) and the outcome. A warning the first
/// time the line search stalls, and the first time newton_iterations > 1 ends unconverged;
/// later ones are counted at the end of the run. Divergences (DivergenceMonitor.h, after
/// onDivergence): a linear solve stopped above maxLinearResidual, and a stalled Newton
/// iteration: the line search found no step that lowers |R| (above round-off) and the solver
/// stayed at the last point (not when a NewtonRaphsonSolver asks for the full step), or
/// newton_iterations > 1 ended unconverged with |R| not below |R_0|. No energy check: a static
/// solver has no velocities.
class StaticSolver final : public OdeSolver {
 public:
  Data<int> d_newtonIterations{this,
                               "newton_iterations",
                               1,
                               "Newton iterations per time step (load increment).",
                               {.min = 1.0, .max = 100000.0}};
  Data<double> d_absoluteCorrection{this,
                                    "absolute_correction_tolerance_threshold",
                                    1e-5,
                                    "Stop when the norm of the correction |du| falls below "
                                    "this (<= 0: disabled).",
                                    {.unit = "m"}};
  Data<double> d_relativeCorrection{this, "relative_correction_tolerance_threshold", 1e-5,
                                    "Stop when |du| / |U| falls below this, U the displacement "
                                    "of the step so far (<= 0: disabled)."};
  Data<double> d_absoluteResidual{this,
                                  "absolute_residual_tolerance_threshold",
                                  1e-5,
                                  "Stop when the residual norm |R| falls below this "
                                  "(<= 0: disabled).",
                                  {.unit = "N"}};
  Data<double> d_relativeResidual{this, "relative_residual_tolerance_threshold", 1e-5,
                                  "Stop when |R| / |R_0| falls below this (<= 0: disabled)."};
  Data<bool> d_shouldDiverge{this, "should_diverge_when_residual_is_growing", false,
                             "Stop the iterations when the residual grows (possible only "
                             "with maxNbIterationsLineSearch = 1)."};
  Data<int> d_lineSearchIterations{this,
                                   "maxNbIterationsLineSearch",
                                   10,
                                   "Step lengths the line search tries: 1, 1/2, 1/4, ... "
                                   "(1: full Newton steps). SOFA's NewtonRaphsonSolver name.",
                                   {.min = 1.0, .max = 60.0}};
  Data<int> d_lastIterations{
      this, "lastIterations", 0, "Newton iterations of the last step.", {.output = true}};
  Data<double> d_lastResidual{this,
                              "lastResidual",
                              0.0,
                              "Residual norm |R| at the end of the last step.",
                              {.unit = "N", .output = true}};
  Data<bool> d_lastConverged{this,
                             "lastConverged",
                             false,
                             "Whether a convergence criterion was met in the last step.",
                             {.output = true}};
  Link<LinearSolver> l_linearSolver{this, "linearSolver", "Linear solver (default: the node's)."};
  Link<NewtonRaphsonSolver> l_newtonSolver{this, "newtonSolver",
                                           "Newton parameters (default: this component's)."};

  void init() override;
  void solve(MechanicalOperations& mop, double dt) override;
  bool constraintResponse(double dt, ConstraintResponse& response) const override;
  void cleanup() override;

 private:
  NewtonSettings settings() const;
  void setStatus(const char* status);

  long long m_step = 0;
  long long m_unconverged = 0;
  long long m_stalls = 0;
  DivergenceMonitor m_divergence{*this};
  LinearSolveCheck m_linear{*this};
};

}  // namespace stroma
