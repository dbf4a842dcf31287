// SPDX-License-Identifier: MIT
// Trilinear hexahedron: shape functions, volume, mass, and the stiffness against linear
// tetrahedra splits of the same cube.
#include "SolidMechanics/kernels/TrilinearHexahedron.h"

#include <gtest/gtest.h>

#include <array>
#include <random>

#include "FemTestUtilities.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"

namespace stroma::fem {
namespace {

using test::distortedHexahedron;
using test::testElasticity;
using test::unitCube;

TEST(TrilinearHexahedron, ShapeFunctionsAreKroneckerAtCornersAndPartitionUnity) {
  for (int i = 0; i < 8; ++i) {
    const Vector8d N = computeHexahedronShapeFunctions(hexahedronReferenceCorner(i));
    EXPECT_TRUE(N.isApprox(Vector8d::Unit(i))) << "node " << i;
    // The SOFA node order: node i of the unit cube is (s_i + 1) / 2.
    EXPECT_TRUE(
        unitCube().col(i).isApprox(((hexahedronReferenceCorner(i).array() + 1) / 2).matrix()));
  }
  const Eigen::Vector3d xi(0.3, -0.7, 0.1);
  EXPECT_NEAR(computeHexahedronShapeFunctions(xi).sum(), 1, 1e-15);
  EXPECT_TRUE(computeHexahedronReferenceGradients(xi).rowwise().sum().isZero(1e-15));
  // Reference gradients against central differences of the shape functions.
  const double h = 1e-6;
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(a);
    const Vector8d derivative =
        (computeHexahedronShapeFunctions(xi + step) - computeHexahedronShapeFunctions(xi - step)) /
        (2 * h);
    EXPECT_TRUE(
        derivative.isApprox(computeHexahedronReferenceGradients(xi).row(a).transpose(), 1e-9));
  }
}

TEST(TrilinearHexahedron, VolumeIsExactForDistortedShapes) {
  EXPECT_NEAR(computeHexahedronVolume(unitCube()), 1, 1e-14);
  // Compare with the 6-tetrahedron split (exact for planar faces) of a box sheared by A.
  const Eigen::Matrix3d A = (Eigen::Matrix3d() << 2, 0.3, 0.1, 0, 1.5, -0.2, 0, 0, 0.5).finished();
  EXPECT_NEAR(computeHexahedronVolume(A * unitCube()), A.determinant(), 1e-13);
  // A non-planar-faced hexahedron: volume = integral det J, checked against fine quadrature.
  const HexahedronVectors X = distortedHexahedron();
  double fine = 0;
  const int n = 40;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d xi =
            Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5) * (2.0 / n) - Eigen::Vector3d::Ones();
        fine += computeHexahedronJacobian(X, xi).determinant() * (8.0 / (n * n * n));
      }
  EXPECT_NEAR(computeHexahedronVolume(X), fine, 1e-5);
}

TEST(TrilinearHexahedron, ConsistentMassSumsToDensityTimesVolume) {
  const double density = 1070;
  const Matrix8d cube = computeHexahedronConsistentMass(unitCube(), density);
  // Unit cube: M_ij = rho / 27 * 2^(-number of differing coordinates of nodes i and j).
  EXPECT_NEAR(cube(0, 0), density / 27, 1e-12);
  EXPECT_NEAR(cube(0, 1), density / 54, 1e-12);
  EXPECT_NEAR(cube(0, 2), density / 108, 1e-12);
  EXPECT_NEAR(cube(0, 6), density / 216, 1e-12);
  EXPECT_TRUE(computeHexahedronLumpedMass(unitCube(), density)
                  .isApprox(Vector8d::Constant(density / 8), 1e-14));

  const HexahedronVectors X = distortedHexahedron();
  const Matrix8d M = computeHexahedronConsistentMass(X, density);
  EXPECT_TRUE(M.isApprox(M.transpose()));
  EXPECT_NEAR(M.sum(), density * computeHexahedronVolume(X), 1e-10);
  EXPECT_NEAR(computeHexahedronLumpedMass(X, density).sum(), M.sum(), 1e-10);
  // First moment of a sheared box: sum_ij M_ij x_j = rho V centroid.
  const Eigen::Matrix3d A = (Eigen::Matrix3d() << 2, 0.3, 0.1, 0, 1.5, -0.2, 0, 0, 0.5).finished();
  const HexahedronVectors box = A * unitCube();
  const Eigen::Vector3d firstMoment = box * computeHexahedronLumpedMass(box, density);
  EXPECT_TRUE(
      firstMoment.isApprox(density * A.determinant() * A * Eigen::Vector3d::Constant(0.5), 1e-12));
}

/// Energy 1/2 u^T K u of the displacement u of the cube's corners over a list of tetrahedra.
double splitEnergy(const std::vector<std::array<int, 4>>& tetrahedra, const HexahedronVectors& X,
                   const HexahedronVectors& u, const Matrix6d& C, double& volume) {
  double energy = 0;
  volume = 0;
  for (const auto& t : tetrahedra) {
    TetrahedronVectors Xt, ut;
    for (int k = 0; k < 4; ++k) {
      Xt.col(k) = X.col(t[k]);
      ut.col(k) = u.col(t[k]);
    }
    TetrahedronShape shape;
    EXPECT_EQ(computeTetrahedronShape(Xt, shape), ElementStatus::ok);
    const auto v = asElementVector<4>(ut);
    energy += 0.5 * v.dot(computeTetrahedronStiffness(shape, C) * v);
    volume += std::abs(shape.volume);
  }
  return energy;
}

TEST(TrilinearHexahedron, StiffnessMatchesTetrahedraSplitsOnLinearFields) {
  // Five tetrahedra: the corner tetrahedra of 0, 2, 5, 7 and the central one (1, 3, 4, 6).
  const std::vector<std::array<int, 4>> five = {
      {0, 1, 3, 4}, {2, 1, 3, 6}, {5, 1, 4, 6}, {7, 3, 4, 6}, {1, 3, 4, 6}};
  // Six tetrahedra around the diagonal 0-6.
  const std::vector<std::array<int, 4>> six = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                               {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  const Matrix6d C = testElasticity(1e4, 0.45);
  const HexahedronVectors X = unitCube();
  Matrix24d Ke;
  ASSERT_EQ(computeHexahedronStiffness(X, C, Ke), ElementStatus::ok);
  std::mt19937 rng(8);
  for (int trial = 0; trial < 5; ++trial) {
    // Patch field: u = H X + c gives a uniform strain, represented exactly by both elements.
    const Eigen::Matrix3d H = test::randomVectors<3>(rng, 0.01);
    const HexahedronVectors u = (H * X).colwise() + Eigen::Vector3d(0.1, 0.2, -0.3);
    const auto v = asElementVector<8>(u);
    const double hexaEnergy = 0.5 * v.dot(Ke * v);
    double volume5 = 0, volume6 = 0;
    EXPECT_NEAR(splitEnergy(five, X, u, C, volume5), hexaEnergy, 1e-12 * hexaEnergy);
    EXPECT_NEAR(splitEnergy(six, X, u, C, volume6), hexaEnergy, 1e-12 * hexaEnergy);
    EXPECT_NEAR(volume5, 1, 1e-14);
    EXPECT_NEAR(volume6, 1, 1e-14);
  }
}

TEST(TrilinearHexahedron, GradientsReproduceLinearFieldsInDistortedShapes) {
  const HexahedronVectors X = distortedHexahedron();
  const Eigen::Vector3d xi(0.2, -0.4, 0.6);
  HexahedronVectors gradients;
  double detJ = 0;
  ASSERT_EQ(computeHexahedronGradients(X, xi, gradients, detJ), ElementStatus::ok);
  EXPECT_GT(detJ, 0);
  EXPECT_TRUE((X * gradients.transpose()).isIdentity(1e-13));
  EXPECT_TRUE(gradients.rowwise().sum().isZero(1e-13));
}

TEST(TrilinearHexahedron, InvertedCornerIsDegenerate) {
  HexahedronVectors X = unitCube();
  X.col(6) = Eigen::Vector3d(-0.5, -0.5, -0.5);  // node 6 pulled through node 0
  Matrix24d Ke;
  EXPECT_EQ(computeHexahedronStiffness(X, testElasticity(), Ke), ElementStatus::degenerate);
  // A left-handed numbering (mirror image) is not degenerate and has the same stiffness.
  const HexahedronVectors mirrored = Eigen::Vector3d(1, 1, -1).asDiagonal() * unitCube();
  Matrix24d mirroredKe, cubeKe;
  ASSERT_EQ(computeHexahedronStiffness(unitCube(), testElasticity(), cubeKe), ElementStatus::ok);
  ASSERT_EQ(computeHexahedronStiffness(mirrored, testElasticity(), mirroredKe), ElementStatus::ok);
  EXPECT_LT(computeHexahedronVolume(mirrored), 0);
  Matrix24d reflection = Matrix24d::Identity();
  for (int i = 0; i < 8; ++i) reflection(3 * i + 2, 3 * i + 2) = -1;
  EXPECT_TRUE((reflection * mirroredKe * reflection).isApprox(cubeKe, 1e-12));
}

}  // namespace
}  // namespace stroma::fem
