// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/CorotationalTetrahedron.h"

#include <Eigen/LU>
#include <cmath>

#include "SolidMechanics/kernels/LinearTetrahedron.h"

namespace stroma::fem {

namespace {

Eigen::Matrix3d edgeFrame(const TetrahedronVectors& x) {
  return computeFrameFromEdges(x.col(1) - x.col(0), x.col(2) - x.col(0));
}

}  // namespace

ElementStatus computeCorotationalTetrahedron(const TetrahedronVectors& rest, const Matrix6d& C,
                                             CorotationalTetrahedron& element) {
  TetrahedronShape shape;
  if (computeTetrahedronShape(rest, shape) != ElementStatus::ok) return ElementStatus::degenerate;
  element.restPositions = rest;
  element.restFrameTransposed = edgeFrame(rest).transpose();
  // grad N_j (j = 1..3) are the rows of Dm^-1.
  element.restEdgesInverse = shape.gradients.rightCols<3>().transpose();
  element.stiffness = computeTetrahedronStiffness(shape, C);
  element.restVolume = shape.volume;
  return ElementStatus::ok;
}

Eigen::Matrix3d computeDeformationGradient(const CorotationalTetrahedron& element,
                                           const TetrahedronVectors& x) {
  Eigen::Matrix3d Ds;
  Ds << x.col(1) - x.col(0), x.col(2) - x.col(0), x.col(3) - x.col(0);
  return Ds * element.restEdgesInverse;
}

Eigen::Matrix3d computeRotation(RotationMethod method, const CorotationalTetrahedron& element,
                                const TetrahedronVectors& x) {
  switch (method) {
    case RotationMethod::small:
      return Eigen::Matrix3d::Identity();
    case RotationMethod::large:
      return edgeFrame(x) * element.restFrameTransposed;
    case RotationMethod::polar:
      return computePolarRotation(computeDeformationGradient(element, x));
    case RotationMethod::svd:
      return computeSvdRotation(computeDeformationGradient(element, x));
  }
  return Eigen::Matrix3d::Identity();
}

TetrahedronRows computeStiffnessFactor(const CorotationalTetrahedron& element, double scale) {
  // grad N_j (j = 1..3) are the rows of Dm^-1; grad N_0 = -(their sum).
  TetrahedronVectors G;
  G.rightCols<3>() = element.restEdgesInverse.transpose();
  G.col(0) = -G.rightCols<3>().rowwise().sum();
  return toRows(std::sqrt(scale * std::abs(element.restVolume)) * G);
}

}  // namespace stroma::fem
