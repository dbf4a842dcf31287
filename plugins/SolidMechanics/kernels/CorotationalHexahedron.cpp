// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/CorotationalHexahedron.h"

#include <Eigen/LU>

#include "SolidMechanics/kernels/TrilinearHexahedron.h"

namespace stroma::fem {

ElementStatus computeCorotationalHexahedron(const HexahedronVectors& rest, const Matrix6d& C,
                                            CorotationalHexahedron& element) {
  double centreDetJ = 0;
  if (computeHexahedronStiffness(rest, C, element.stiffness) != ElementStatus::ok ||
      computeHexahedronGradients(rest, Eigen::Vector3d::Zero(), element.centreGradients,
                                 centreDetJ) != ElementStatus::ok) {
    return ElementStatus::degenerate;
  }
  element.restPositions = rest;
  element.restFrameTransposed = computeHexahedronFrame(rest).transpose();
  element.restVolume = computeHexahedronVolume(rest);
  return ElementStatus::ok;
}

Eigen::Matrix3d computeHexahedronFrame(const HexahedronVectors& x) {
  const Eigen::Vector3d alongXi =
      (x.col(1) - x.col(0) + x.col(2) - x.col(3) + x.col(5) - x.col(4) + x.col(6) - x.col(7)) / 4;
  const Eigen::Vector3d alongEta =
      (x.col(3) - x.col(0) + x.col(2) - x.col(1) + x.col(7) - x.col(4) + x.col(6) - x.col(5)) / 4;
  return computeFrameFromEdges(alongXi, alongEta);
}

Eigen::Matrix3d computeCentreDeformationGradient(const CorotationalHexahedron& element,
                                                 const HexahedronVectors& x) {
  return x * element.centreGradients.transpose();
}

Eigen::Matrix3d computeRotation(RotationMethod method, const CorotationalHexahedron& element,
                                const HexahedronVectors& x) {
  switch (method) {
    case RotationMethod::small:
      return Eigen::Matrix3d::Identity();
    case RotationMethod::large:
      return computeHexahedronFrame(x) * element.restFrameTransposed;
    case RotationMethod::polar: {
      const Eigen::Matrix3d F = computeCentreDeformationGradient(element, x);
      if (F.determinant() <= 0) return computeHexahedronFrame(x) * element.restFrameTransposed;
      return computePolarRotation(F);
    }
    case RotationMethod::svd:
      return computeSvdRotation(computeCentreDeformationGradient(element, x));
  }
  return Eigen::Matrix3d::Identity();
}

}  // namespace stroma::fem
