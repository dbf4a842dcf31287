// SPDX-License-Identifier: MIT
// Linear tetrahedron: gradients, signed volume, strain-displacement, stiffness, force.
#include "SolidMechanics/kernels/LinearTetrahedron.h"

#include <gtest/gtest.h>

#include <random>

#include "FemTestUtilities.h"
#include "SolidMechanics/kernels/StrainDisplacement.h"

namespace stroma::fem {
namespace {

using test::irregularTetrahedron;
using test::testElasticity;

/// Voigt strain (engineering shear) of a displacement gradient H = du/dX.
Vector6d voigtStrain(const Eigen::Matrix3d& H) {
  const Eigen::Matrix3d e = 0.5 * (H + H.transpose());
  return (Vector6d() << e(0, 0), e(1, 1), e(2, 2), 2 * e(0, 1), 2 * e(1, 2), 2 * e(2, 0))
      .finished();
}

TEST(LinearTetrahedron, UnitTetrahedronVolumeAndGradients) {
  TetrahedronVectors X;
  X << 0, 1, 0, 0,  //
      0, 0, 1, 0,   //
      0, 0, 0, 1;
  TetrahedronShape shape;
  ASSERT_EQ(computeTetrahedronShape(X, shape), ElementStatus::ok);
  EXPECT_DOUBLE_EQ(shape.volume, 1.0 / 6);
  TetrahedronVectors expected;
  expected << -1, 1, 0, 0,  //
      -1, 0, 1, 0,          //
      -1, 0, 0, 1;
  EXPECT_TRUE(shape.gradients.isApprox(expected));
  // Swapping two nodes flips the sign of the volume.
  X.col(1).swap(X.col(2));
  EXPECT_DOUBLE_EQ(computeTetrahedronVolume(X), -1.0 / 6);
}

TEST(LinearTetrahedron, GradientsReproduceLinearFields) {
  const TetrahedronVectors X = irregularTetrahedron();
  TetrahedronShape shape;
  ASSERT_EQ(computeTetrahedronShape(X, shape), ElementStatus::ok);
  EXPECT_TRUE(shape.gradients.rowwise().sum().isZero(1e-14));
  // sum_i X_i grad N_i^T = I: the element interpolates x = X exactly.
  EXPECT_TRUE((X * shape.gradients.transpose()).isIdentity(1e-14));
  // B u = eps for a linear field u = H X + c.
  std::mt19937 rng(1);
  const Eigen::Matrix3d H = test::randomVectors<3>(rng, 0.1);
  const TetrahedronVectors u = (H * X).colwise() + Eigen::Vector3d(0.3, -0.2, 0.5);
  const Vector6d strain = computeStrainDisplacement<4>(shape.gradients) * asElementVector<4>(u);
  EXPECT_TRUE(strain.isApprox(voigtStrain(H), 1e-12));
}

TEST(LinearTetrahedron, ForceOfUniformStrainIsStressOnFaces) {
  // For a uniform stress sigma, f_i = -V sigma grad N_i, and -V grad N_i is the area-weighted
  // outward normal (A n / 3) of the face opposite node i.
  const TetrahedronVectors X = irregularTetrahedron();
  TetrahedronShape shape;
  ASSERT_EQ(computeTetrahedronShape(X, shape), ElementStatus::ok);
  const Matrix6d C = testElasticity();
  std::mt19937 rng(2);
  const Eigen::Matrix3d H = test::randomVectors<3>(rng, 0.01);
  const Vector6d s = C * voigtStrain(H);
  Eigen::Matrix3d sigma;
  sigma << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  const TetrahedronVectors f = computeLinearForce(computeTetrahedronStiffness(shape, C), H * X);
  EXPECT_TRUE(f.isApprox(-shape.volume * sigma * shape.gradients, 1e-12));
  // Face (1, 2, 3) opposite node 0 has outward normal (x2-x1) x (x3-x1) / 2 for this orientation.
  const Eigen::Vector3d areaNormal = 0.5 * (X.col(2) - X.col(1)).cross(X.col(3) - X.col(1));
  EXPECT_TRUE(f.col(0).isApprox(sigma * areaNormal / 3, 1e-12));
}

TEST(LinearTetrahedron, StiffnessIsEnergyOfStrainAndIndependentOfOrientation) {
  const TetrahedronVectors X = irregularTetrahedron();
  const Matrix6d C = testElasticity(3000, 0.4);
  TetrahedronShape shape, mirroredShape;
  ASSERT_EQ(computeTetrahedronShape(X, shape), ElementStatus::ok);
  const Matrix12d Ke = computeTetrahedronStiffness(shape, C);
  std::mt19937 rng(4);
  const Eigen::Matrix3d H = test::randomVectors<3>(rng, 0.01);
  const TetrahedronVectors displacement = H * X;
  const auto u = asElementVector<4>(displacement);
  const Vector6d strain = voigtStrain(H);
  EXPECT_NEAR(0.5 * u.dot(Ke * u), 0.5 * shape.volume * strain.dot(C * strain), 1e-14);

  // Swapping nodes 1 and 2 permutes Ke's blocks and keeps it positive.
  TetrahedronVectors mirrored = X;
  mirrored.col(1).swap(mirrored.col(2));
  ASSERT_EQ(computeTetrahedronShape(mirrored, mirroredShape), ElementStatus::ok);
  EXPECT_LT(mirroredShape.volume, 0);
  Eigen::PermutationMatrix<12> swap12;
  swap12.indices() << 0, 1, 2, 6, 7, 8, 3, 4, 5, 9, 10, 11;
  const Matrix12d permuted =
      swap12.transpose() * computeTetrahedronStiffness(mirroredShape, C) * swap12;
  EXPECT_TRUE(permuted.isApprox(Ke, 1e-12));
}

TEST(LinearTetrahedron, StiffnessBlocksAreTensorMassEdgeTensors) {
  // Picinbono et al. (seed 004, eq. 8): Ke_jk = V (lambda g_j g_k^T + mu g_k g_j^T
  // + mu (g_j . g_k) I).
  const TetrahedronVectors X = irregularTetrahedron();
  const LameParameters lame = computeLameParameters(2000, 0.35);
  TetrahedronShape shape;
  ASSERT_EQ(computeTetrahedronShape(X, shape), ElementStatus::ok);
  const Matrix12d Ke = computeTetrahedronStiffness(shape, computeElasticityMatrix(lame));
  for (int j = 0; j < 4; ++j) {
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d gj = shape.gradients.col(j), gk = shape.gradients.col(k);
      const Eigen::Matrix3d expected =
          shape.volume * (lame.lambda * gj * gk.transpose() + lame.mu * gk * gj.transpose() +
                          lame.mu * gj.dot(gk) * Eigen::Matrix3d::Identity());
      EXPECT_TRUE((Ke.block<3, 3>(3 * j, 3 * k).isApprox(expected, 1e-12))) << j << ", " << k;
    }
  }
}

TEST(LinearTetrahedron, FlatTetrahedronIsDegenerate) {
  TetrahedronVectors X;
  X << 0, 1, 0, 1,  //
      0, 0, 1, 1,   //
      0, 0, 0, 0;
  TetrahedronShape shape;
  EXPECT_EQ(computeTetrahedronShape(X, shape), ElementStatus::degenerate);
  X(2, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(computeTetrahedronShape(X, shape), ElementStatus::degenerate);
}

}  // namespace
}  // namespace stroma::fem
