// SPDX-License-Identifier: MIT
// The parameters of StaticSolver's Newton-Raphson iterations, filled from its own fields or
// from a linked NewtonRaphsonSolver. A threshold <= 0 disables its criterion.
#pragma once

namespace stroma {

struct NewtonSettings {
  int iterations = 1;                ///< Newton iterations per time step
  double absoluteResidual = 1e-5;    ///< |R| <= this
  double relativeInitial = 1e-5;     ///< |R_k| / |R_0| <= this
  double relativeSuccessive = 0;     ///< |R_k| / |R_{k-1}| <= this
  double absoluteCorrection = 1e-5;  ///< |x_k - x_{k-1}| <= this
  double relativeCorrection = 1e-5;  ///< |x_k - x_{k-1}| / |x_k - x_start| <= this
  int lineSearchTrials = 10;         ///< step lengths tried: 1, c, c^2, ... (1: full steps only)
  double lineSearchCoefficient = 0.5;
  bool fullStepWhenLineSearchFails = false;  ///< else stay at the last point and stop
  bool stopWhenResidualGrows = false;
  bool warnWhenLineSearchFails = true;
  bool warnWhenNotConverged = true;
};

}  // namespace stroma
