// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/IsotropicMaterial.h"

#include <cmath>

namespace stroma::fem {

bool isValidIsotropicMaterial(double youngModulus, double poissonRatio) {
  return std::isfinite(youngModulus) && std::isfinite(poissonRatio) && youngModulus > 0 &&
         poissonRatio > -1 && poissonRatio < 0.5;
}

LameParameters computeLameParameters(double youngModulus, double poissonRatio) {
  const double nu = poissonRatio;
  return {youngModulus * nu / ((1 + nu) * (1 - 2 * nu)), youngModulus / (2 * (1 + nu))};
}

Matrix6d computeElasticityMatrix(const LameParameters& lame) {
  Matrix6d C = Matrix6d::Zero();
  C.topLeftCorner<3, 3>().setConstant(lame.lambda);
  C.diagonal().head<3>().array() += 2 * lame.mu;
  C.diagonal().tail<3>().setConstant(lame.mu);
  return C;
}

}  // namespace stroma::fem
