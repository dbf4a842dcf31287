// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "NewtonSettings.h"
#include "core/Base.h"

namespace stroma {

/// The Newton-Raphson parameters of a StaticSolver that links it (`newtonSolver="@..."`),
/// with the names of SOFA's NewtonRaphsonSolver, and the outcome of its last solve (`status`).
/// It computes nothing itself: StaticSolver runs the iterations (see StaticSolver.h).
///
/// Differences with SOFA: a line-search trial is accepted on Armijo's sufficient decrease
/// |R(x + a du)| <= (1 - 1e-4 a) |R(x)| (SOFA: any decrease), and the relative estimate
/// difference is measured against the displacement of the step (Stroma's states may be rigid
/// frames, whose positions have no norm).
class NewtonRaphsonSolver final : public Base {
 public:
  Data<int> d_maxNbIterationsNewton{this,
                                    "maxNbIterationsNewton",
                                    1,
                                    "Newton iterations per time step (load increment).",
                                    {.min = 1.0, .max = 100000.0}};
  Data<double> d_relativeSuccessiveStoppingThreshold{
      this, "relativeSuccessiveStoppingThreshold", 1e-5,
      "Stop when |R_k| / |R_k-1| falls below this (0: disabled)."};
  Data<double> d_relativeInitialStoppingThreshold{
      this, "relativeInitialStoppingThreshold", 1e-5,
      "Stop when |R_k| / |R_0| falls below this (0: disabled)."};
  Data<double> d_absoluteResidualStoppingThreshold{
      this,
      "absoluteResidualStoppingThreshold",
      1e-5,
      "Stop when |R_k| falls below this (0: disabled).",
      {.unit = "N"}};
  Data<double> d_relativeEstimateDifferenceThreshold{
      this, "relativeEstimateDifferenceThreshold", 0.0,
      "Stop when |x_k - x_k-1| / |x_k - x_start| falls below this (0: disabled)."};
  Data<double> d_absoluteEstimateDifferenceThreshold{
      this,
      "absoluteEstimateDifferenceThreshold",
      0.0,
      "Stop when |x_k - x_k-1| falls below this (0: disabled).",
      {.unit = "m"}};
  Data<int> d_maxNbIterationsLineSearch{this,
                                        "maxNbIterationsLineSearch",
                                        5,
                                        "Step lengths the line search tries: 1, c, c^2, ... "
                                        "(1: full Newton steps).",
                                        {.min = 1.0, .max = 60.0}};
  Data<double> d_lineSearchCoefficient{this,
                                       "lineSearchCoefficient",
                                       0.5,
                                       "Factor c between successive step lengths.",
                                       {.min = 1e-6, .max = 1.0}};
  Data<bool> d_updateStateWhenDiverged{this, "updateStateWhenDiverged", true,
                                       "When the line search finds no decrease: take the full "
                                       "step anyway (true) or stay and stop (false)."};
  Data<bool> d_warnWhenLineSearchFails{this, "warnWhenLineSearchFails", true,
                                       "Warn when the line search finds no decrease."};
  Data<bool> d_warnWhenDiverge{this, "warnWhenDiverge", true,
                               "Warn when the iterations end without convergence."};
  Data<std::string> d_status{this,
                             "status",
                             "Undefined",
                             "Outcome of the last solve: Running, ConvergedEquilibrium, "
                             "Converged<criterion>, DivergedLineSearch, DivergedMaxIterations.",
                             {.output = true}};

  /// The parameters, in the form StaticSolver uses.
  NewtonSettings settings() const;
};

}  // namespace stroma
