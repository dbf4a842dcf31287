// SPDX-License-Identifier: MIT
#include "TensorMass/kernels/VolumePenalty.h"

#include <Eigen/Geometry>
#include <cmath>

#include "SolidMechanics/kernels/LinearTetrahedron.h"
#include "topology/MeshAdjacency.h"

namespace stroma::tensormass {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

Matrix3d crossMatrix(const Vector3d& v) {
  Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// s = (V - V0) / V0 and dV/dx.
struct VolumeState {
  double s;
  fem::TetrahedronVectors gradients;
};

VolumeState computeVolumeState(const fem::TetrahedronVectors& x, double restVolume) {
  return {(fem::computeTetrahedronVolume(x) - restVolume) / restVolume, computeVolumeGradients(x)};
}

}  // namespace

fem::TetrahedronVectors computeVolumeGradients(const fem::TetrahedronVectors& x) {
  // Face (i, j, k) opposite p is oriented outwards (kTetrahedronFaces) for a positive
  // tetrahedron: moving p along its inward normal increases V.
  fem::TetrahedronVectors g;
  for (int p = 0; p < 4; ++p) {
    const auto& face = kTetrahedronFaces[p];
    const Vector3d e1 = x.col(face[1]) - x.col(face[0]), e2 = x.col(face[2]) - x.col(face[0]);
    g.col(p) = -e1.cross(e2) / 6;
  }
  return g;
}

double computeVolumePenaltyEnergy(const fem::TetrahedronVectors& x, double restVolume,
                                  double gamma) {
  const double s = (fem::computeTetrahedronVolume(x) - restVolume) / restVolume;
  return gamma * std::abs(restVolume) * std::abs(s * s * s) / 3;
}

fem::TetrahedronVectors computeVolumePenaltyForce(const fem::TetrahedronVectors& x,
                                                  double restVolume, double gamma) {
  const VolumeState state = computeVolumeState(x, restVolume);
  // dW/dx = gamma |V0| s |s| ds/dx = gamma sign(V0) s |s| dV/dx.
  const double scale = gamma * std::copysign(1.0, restVolume) * state.s * std::abs(state.s);
  return -scale * state.gradients;
}

fem::TetrahedronVectors computeVolumePenaltyHessianProduct(const fem::TetrahedronVectors& x,
                                                           double restVolume, double gamma,
                                                           const fem::TetrahedronVectors& dx) {
  const VolumeState state = computeVolumeState(x, restVolume);
  const double dV = (state.gradients.array() * dx.array()).sum();
  fem::TetrahedronVectors result =
      (gamma * 2 * std::abs(state.s) / std::abs(restVolume) * dV) * state.gradients;
  // d(dV/dx_p) along dx: face (i, j, k) opposite p, g_p = -(x_j - x_i) x (x_k - x_i) / 6.
  const double curvature = gamma * std::copysign(1.0, restVolume) * state.s * std::abs(state.s);
  if (curvature != 0)
    for (int p = 0; p < 4; ++p) {
      const auto& face = kTetrahedronFaces[p];
      const Vector3d e1 = x.col(face[1]) - x.col(face[0]), e2 = x.col(face[2]) - x.col(face[0]);
      const Vector3d de1 = dx.col(face[1]) - dx.col(face[0]),
                     de2 = dx.col(face[2]) - dx.col(face[0]);
      result.col(p) -= curvature * (de1.cross(e2) + e1.cross(de2)) / 6;
    }
  return result;
}

fem::Matrix12d computeVolumePenaltyHessian(const fem::TetrahedronVectors& x, double restVolume,
                                           double gamma) {
  const VolumeState state = computeVolumeState(x, restVolume);
  const auto g = fem::asElementVector<4>(state.gradients);
  fem::Matrix12d H = (gamma * 2 * std::abs(state.s) / std::abs(restVolume)) * g * g.transpose();
  const double curvature = gamma * std::copysign(1.0, restVolume) * state.s * std::abs(state.s);
  if (curvature != 0)
    for (int p = 0; p < 4; ++p) {
      // dg_p = ([e2]x (dx_j - dx_i) - [e1]x (dx_k - dx_i)) / 6.
      const auto& face = kTetrahedronFaces[p];
      const int i = face[0], j = face[1], k = face[2];
      const Vector3d e1 = x.col(j) - x.col(i), e2 = x.col(k) - x.col(i);
      const Matrix3d dj = crossMatrix(e2) / 6, dk = -crossMatrix(e1) / 6;
      H.block<3, 3>(3 * p, 3 * j) += curvature * dj;
      H.block<3, 3>(3 * p, 3 * k) += curvature * dk;
      H.block<3, 3>(3 * p, 3 * i) -= curvature * (dj + dk);
    }
  return H;
}

}  // namespace stroma::tensormass
