// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/TrilinearHexahedron.h"

#include <Eigen/LU>
#include <array>
#include <cmath>

#include "SolidMechanics/kernels/StrainDisplacement.h"

namespace stroma::fem {

namespace {

// clang-format off
constexpr std::array<std::array<double, 3>, 8> kCorners = {{
    {-1, -1, -1}, {+1, -1, -1}, {+1, +1, -1}, {-1, +1, -1},
    {-1, -1, +1}, {+1, -1, +1}, {+1, +1, +1}, {-1, +1, +1}}};
// clang-format on

/// Calls visit(xi, weight) at the points of the tensor Gauss rule with 2 or 3 points per axis.
template <class Visit>
void forEachGaussPoint(int pointsPerAxis, Visit&& visit) {
  const double a2 = 1.0 / std::sqrt(3.0), a3 = std::sqrt(0.6);
  const std::array<double, 3> points2 = {-a2, a2, 0}, weights2 = {1, 1, 0};
  const std::array<double, 3> points3 = {-a3, 0, a3}, weights3 = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  const auto& points = pointsPerAxis == 2 ? points2 : points3;
  const auto& weights = pointsPerAxis == 2 ? weights2 : weights3;
  for (int k = 0; k < pointsPerAxis; ++k)
    for (int j = 0; j < pointsPerAxis; ++j)
      for (int i = 0; i < pointsPerAxis; ++i)
        visit(Eigen::Vector3d(points[i], points[j], points[k]),
              weights[i] * weights[j] * weights[k]);
}

}  // namespace

Eigen::Vector3d hexahedronReferenceCorner(int node) {
  return {kCorners[node][0], kCorners[node][1], kCorners[node][2]};
}

Vector8d computeHexahedronShapeFunctions(const Eigen::Vector3d& xi) {
  Vector8d N;
  for (int i = 0; i < 8; ++i) {
    const auto& s = kCorners[i];
    N[i] = (1 + s[0] * xi[0]) * (1 + s[1] * xi[1]) * (1 + s[2] * xi[2]) / 8;
  }
  return N;
}

HexahedronVectors computeHexahedronReferenceGradients(const Eigen::Vector3d& xi) {
  HexahedronVectors G;
  for (int i = 0; i < 8; ++i) {
    const auto& s = kCorners[i];
    const double a = 1 + s[0] * xi[0], b = 1 + s[1] * xi[1], c = 1 + s[2] * xi[2];
    G.col(i) << s[0] * b * c / 8, a * s[1] * c / 8, a * b * s[2] / 8;
  }
  return G;
}

Eigen::Matrix3d computeHexahedronJacobian(const HexahedronVectors& x, const Eigen::Vector3d& xi) {
  return x * computeHexahedronReferenceGradients(xi).transpose();
}

ElementStatus computeHexahedronGradients(const HexahedronVectors& rest, const Eigen::Vector3d& xi,
                                         HexahedronVectors& gradients, double& detJ) {
  if (!rest.allFinite()) return ElementStatus::degenerate;
  const HexahedronVectors referenceGradients = computeHexahedronReferenceGradients(xi);
  const Eigen::Matrix3d J = rest * referenceGradients.transpose();
  detJ = J.determinant();
  const double scale = J.norm() / std::sqrt(3.0);
  if (!(std::abs(detJ) > 1e-12 * scale * scale * scale)) return ElementStatus::degenerate;
  gradients = J.inverse().transpose() * referenceGradients;
  return ElementStatus::ok;
}

double computeHexahedronVolume(const HexahedronVectors& x) {
  double volume = 0;
  forEachGaussPoint(2, [&](const Eigen::Vector3d& xi, double weight) {
    volume += weight * computeHexahedronJacobian(x, xi).determinant();
  });
  return volume;
}

ElementStatus computeHexahedronStiffness(const HexahedronVectors& rest, const Matrix6d& C,
                                         Matrix24d& Ke) {
  Ke.setZero();
  ElementStatus status = ElementStatus::ok;
  double firstDetJ = 0;
  forEachGaussPoint(2, [&](const Eigen::Vector3d& xi, double weight) {
    HexahedronVectors gradients;
    double detJ = 0;
    if (computeHexahedronGradients(rest, xi, gradients, detJ) != ElementStatus::ok ||
        detJ * (firstDetJ == 0 ? detJ : firstDetJ) <= 0) {
      status = ElementStatus::degenerate;
      return;
    }
    firstDetJ = detJ;
    const Eigen::Matrix<double, 6, 24> B = computeStrainDisplacement<8>(gradients);
    const Eigen::Matrix<double, 6, 24> CB = C * B;
    Ke.noalias() += (weight * std::abs(detJ)) * B.transpose() * CB;
  });
  Ke = 0.5 * (Ke + Ke.transpose()).eval();
  return status;
}

Matrix8d computeHexahedronConsistentMass(const HexahedronVectors& rest, double density) {
  // N_i N_j det J has degree <= 4 per reference axis: 3 Gauss points per axis are exact.
  Matrix8d M = Matrix8d::Zero();
  forEachGaussPoint(3, [&](const Eigen::Vector3d& xi, double weight) {
    const Vector8d N = computeHexahedronShapeFunctions(xi);
    const double detJ = computeHexahedronJacobian(rest, xi).determinant();
    M.noalias() += (density * weight * std::abs(detJ)) * N * N.transpose();
  });
  return M;
}

Vector8d computeHexahedronLumpedMass(const HexahedronVectors& rest, double density) {
  return computeHexahedronConsistentMass(rest, density).rowwise().sum();
}

}  // namespace stroma::fem
