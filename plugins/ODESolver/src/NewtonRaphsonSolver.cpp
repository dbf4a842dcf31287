// SPDX-License-Identifier: MIT
#include "NewtonRaphsonSolver.h"

namespace stroma {

NewtonSettings NewtonRaphsonSolver::settings() const {
  NewtonSettings s;
  s.iterations = d_maxNbIterationsNewton.value();
  s.absoluteResidual = d_absoluteResidualStoppingThreshold.value();
  s.relativeInitial = d_relativeInitialStoppingThreshold.value();
  s.relativeSuccessive = d_relativeSuccessiveStoppingThreshold.value();
  s.absoluteCorrection = d_absoluteEstimateDifferenceThreshold.value();
  s.relativeCorrection = d_relativeEstimateDifferenceThreshold.value();
  s.lineSearchTrials = d_maxNbIterationsLineSearch.value();
  s.lineSearchCoefficient = d_lineSearchCoefficient.value();
  s.fullStepWhenLineSearchFails = d_updateStateWhenDiverged.value();
  s.stopWhenResidualGrows = false;
  s.warnWhenLineSearchFails = d_warnWhenLineSearchFails.value();
  s.warnWhenNotConverged = d_warnWhenDiverge.value();
  return s;
}

}  // namespace stroma
