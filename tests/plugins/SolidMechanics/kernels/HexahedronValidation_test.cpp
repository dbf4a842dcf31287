// SPDX-License-Identifier: MIT
// Validation of the hexahedron stiffness on small assembled problems with closed-form answers
// (/work/shared/REFERENCES.md): the MacNeal-Harder 3D patch test on seven distorted hexahedra
// and homogeneous uniaxial stress of a unit cube with roller boundaries.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "FemTestUtilities.h"
#include "SolidMechanics/kernels/CorotationalHexahedron.h"
#include "SolidMechanics/kernels/TrilinearHexahedron.h"

namespace stroma::fem {
namespace {

using Hexahedron = std::array<int, 8>;

/// Dense global stiffness of hexahedra over `points` (3 x n).
Eigen::MatrixXd assembleStiffness(const Eigen::Matrix3Xd& points,
                                  const std::vector<Hexahedron>& hexahedra, const Matrix6d& C) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * points.cols(), 3 * points.cols());
  for (const Hexahedron& h : hexahedra) {
    HexahedronVectors X;
    for (int i = 0; i < 8; ++i) X.col(i) = points.col(h[i]);
    Matrix24d Ke;
    EXPECT_EQ(computeHexahedronStiffness(X, C, Ke), ElementStatus::ok);
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) K.block<3, 3>(3 * h[i], 3 * h[j]) += Ke.block<3, 3>(3 * i, 3 * j);
  }
  return K;
}

/// Solves K u = 0 for the free degrees of freedom, the others prescribed in u.
void solveWithPrescribed(const Eigen::MatrixXd& K, const std::vector<bool>& prescribed,
                         Eigen::VectorXd& u) {
  std::vector<int> free, fixed;
  for (int k = 0; k < static_cast<int>(prescribed.size()); ++k)
    (prescribed[k] ? fixed : free).push_back(k);
  const Eigen::MatrixXd Kff = K(free, free);
  const Eigen::VectorXd rhs = -K(free, fixed) * u(fixed);
  const Eigen::VectorXd freeSolution = Kff.ldlt().solve(rhs);
  u(free) = freeSolution;
}

TEST(HexahedronValidation, MacNealHarderPatchTestIsExact) {
  // Outer corners (unit cube) then the 8 interior nodes, both in SOFA's hexahedron order.
  Eigen::Matrix3Xd points(3, 16);
  points.leftCols<8>() = test::unitCube();
  // clang-format off
  points.rightCols<8>() << 0.249, 0.826, 0.850, 0.273, 0.320, 0.677, 0.788, 0.165,
                           0.342, 0.288, 0.649, 0.750, 0.186, 0.305, 0.693, 0.745,
                           0.192, 0.288, 0.263, 0.230, 0.643, 0.683, 0.644, 0.702;
  // clang-format on
  // The inner hexahedron, then one per cube face: the face quad (cyclic) and its inner image.
  std::vector<Hexahedron> hexahedra = {{8, 9, 10, 11, 12, 13, 14, 15}};
  const std::array<std::array<int, 4>, 6> faces = {
      {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}}};
  for (const auto& f : faces)
    hexahedra.push_back({f[0], f[1], f[2], f[3], f[0] + 8, f[1] + 8, f[2] + 8, f[3] + 8});

  const Matrix6d C = test::testElasticity(1e6, 0.25);
  const Eigen::MatrixXd K = assembleStiffness(points, hexahedra, C);
  // u = 1e-3 (2x + y + z)/2, v = 1e-3 (x + 2y + z)/2, w = 1e-3 (x + y + 2z)/2.
  const Eigen::Matrix3d H =
      1e-3 * (Eigen::Matrix3d() << 1, 0.5, 0.5, 0.5, 1, 0.5, 0.5, 0.5, 1).finished();
  const Eigen::Matrix3Xd exact = H * points;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(48);
  u.head<24>() = exact.leftCols<8>().reshaped();
  std::vector<bool> prescribed(48, false);
  std::fill(prescribed.begin(), prescribed.begin() + 24, true);
  solveWithPrescribed(K, prescribed, u);
  EXPECT_LT((u.tail<24>() - exact.rightCols<8>().reshaped()).cwiseAbs().maxCoeff(), 1e-15);

  // Stress at every Gauss point of every element: sigma = (2000, 2000, 2000, 400, 400, 400).
  const Vector6d expected = (Vector6d() << 2000, 2000, 2000, 400, 400, 400).finished();
  const double g = 1 / std::sqrt(3.0);
  for (const Hexahedron& h : hexahedra) {
    HexahedronVectors X, ue;
    for (int i = 0; i < 8; ++i) {
      X.col(i) = points.col(h[i]);
      ue.col(i) = u.segment<3>(3 * h[i]);
    }
    for (int corner = 0; corner < 8; ++corner) {
      HexahedronVectors gradients;
      double detJ = 0;
      ASSERT_EQ(
          computeHexahedronGradients(X, g * hexahedronReferenceCorner(corner), gradients, detJ),
          ElementStatus::ok);
      const Eigen::Matrix3d Hh = ue * gradients.transpose();
      const Vector6d strain = (Vector6d() << Hh(0, 0), Hh(1, 1), Hh(2, 2), Hh(0, 1) + Hh(1, 0),
                               Hh(1, 2) + Hh(2, 1), Hh(2, 0) + Hh(0, 2))
                                  .finished();
      EXPECT_LT((C * strain - expected).cwiseAbs().maxCoeff(), 1e-8);
    }
  }
}

/// Unit cube stretched to `stretch` along x with rollers on x = 0, y = 0, z = 0 and the face
/// x = 1 displaced: returns the reaction on that face (N) and the lateral strains.
struct UniaxialResult {
  double reaction = 0, lateralY = 0, lateralZ = 0;
};

UniaxialResult solveUniaxial(double stretch, const Matrix6d& C) {
  const HexahedronVectors X = test::unitCube();
  Matrix24d Ke;
  EXPECT_EQ(computeHexahedronStiffness(X, C, Ke), ElementStatus::ok);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(24);
  std::vector<bool> prescribed(24, false);
  for (int i = 0; i < 8; ++i) {
    for (int a = 0; a < 3; ++a) prescribed[3 * i + a] = X(a, i) == 0;  // rollers
    if (X(0, i) == 1) {
      prescribed[3 * i] = true;
      u[3 * i] = stretch - 1;
    }
  }
  solveWithPrescribed(Eigen::MatrixXd(Ke), prescribed, u);
  const Eigen::VectorXd internal = Ke * u;  // = -f: the force the supports must apply
  UniaxialResult result;
  for (int i = 0; i < 8; ++i) {
    if (X(0, i) == 1) result.reaction += internal[3 * i];
    if (X(1, i) == 1) result.lateralY = u[3 * i + 1];
    if (X(2, i) == 1) result.lateralZ = u[3 * i + 2];
  }
  return result;
}

TEST(HexahedronValidation, UniaxialStressOfUnitCube) {
  const double E = 1000, nu = 0.3;
  for (double stretch : {0.9, 1.1, 1.5}) {
    const UniaxialResult r = solveUniaxial(stretch, test::testElasticity(E, nu));
    EXPECT_NEAR(r.reaction, E * (stretch - 1), 1e-9 * E);  // P = E (lambda - 1)
    EXPECT_NEAR(r.lateralY, -nu * (stretch - 1), 1e-12);
    EXPECT_NEAR(r.lateralZ, -nu * (stretch - 1), 1e-12);
  }
}

TEST(HexahedronValidation, CorotationalUniaxialStressIsRotationInvariant) {
  // The linear solution, rotated rigidly, gives the rotated reaction with the corotational
  // force: P = E (lambda - 1) holds in any orientation for the large and polar rotations.
  const double E = 1000, nu = 0.3, stretch = 1.5;
  CorotationalHexahedron element;
  ASSERT_EQ(computeCorotationalHexahedron(test::unitCube(), test::testElasticity(E, nu), element),
            ElementStatus::ok);
  const double lateral = 1 - nu * (stretch - 1);
  const HexahedronVectors deformed =
      Eigen::Vector3d(stretch, lateral, lateral).asDiagonal() * test::unitCube();
  std::mt19937 rng(13);
  const Eigen::Matrix3d Q = test::randomRotation(rng);
  for (RotationMethod method : {RotationMethod::large, RotationMethod::polar}) {
    const HexahedronVectors x = Q * deformed;
    const HexahedronVectors f = computeForce(element, computeRotation(method, element, x), x);
    Eigen::Vector3d faceForce = Eigen::Vector3d::Zero();
    for (int i = 0; i < 8; ++i)
      if (test::unitCube()(0, i) == 1) faceForce += f.col(i);
    // The elastic force on the pulled face is -P A along the rotated x axis.
    EXPECT_TRUE(faceForce.isApprox(-E * (stretch - 1) * Q.col(0), 1e-12));
    // sigma = diag(P, 0, 0): no nodal force across the stretch direction.
    EXPECT_LT((Q.transpose() * f).bottomRows<2>().cwiseAbs().maxCoeff(), 1e-9);
  }
}

}  // namespace
}  // namespace stroma::fem
