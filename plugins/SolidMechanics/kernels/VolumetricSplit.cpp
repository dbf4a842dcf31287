// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/VolumetricSplit.h"

#include <cmath>

#include "SolidMechanics/kernels/TrilinearHexahedron.h"

namespace stroma::fem {

double computeBulkModulus(const LameParameters& lame) { return lame.lambda + 2 * lame.mu / 3; }

Matrix6d computeDeviatoricElasticityMatrix(const LameParameters& lame) {
  Matrix6d C = Matrix6d::Zero();
  C.topLeftCorner<3, 3>().setConstant(-2 * lame.mu / 3);
  C.diagonal().head<3>().array() += 2 * lame.mu;
  C.diagonal().tail<3>().setConstant(lame.mu);
  return C;
}

ElementStatus computeHexahedronMeanGradients(const HexahedronVectors& rest,
                                             HexahedronVectors& meanGradients, double& volume) {
  // The 2 x 2 x 2 Gauss points of the element's stiffness (weights 1): the same rule, so that
  // the volume and the averages are those the deviatoric part integrates on.
  const double a = 1 / std::sqrt(3.0);
  meanGradients.setZero();
  volume = 0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d xi(k & 1 ? a : -a, k & 2 ? a : -a, k & 4 ? a : -a);
    HexahedronVectors gradients;
    double detJ = 0;
    if (computeHexahedronGradients(rest, xi, gradients, detJ) != ElementStatus::ok)
      return ElementStatus::degenerate;
    meanGradients += std::abs(detJ) * gradients;
    volume += std::abs(detJ);
  }
  meanGradients /= volume;
  return ElementStatus::ok;
}

}  // namespace stroma::fem
