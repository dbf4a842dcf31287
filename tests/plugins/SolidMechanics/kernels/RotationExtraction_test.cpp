// SPDX-License-Identifier: MIT
// Rotation extraction: Gram-Schmidt frame, polar decomposition, SVD with inversion handling.
#include "SolidMechanics/kernels/RotationExtraction.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <random>

#include "FemTestUtilities.h"

namespace stroma::fem {
namespace {

using test::randomRotation;

void expectProperRotation(const Eigen::Matrix3d& R) {
  EXPECT_TRUE((R.transpose() * R).isIdentity(1e-12)) << R;
  EXPECT_NEAR(R.determinant(), 1, 1e-12) << R;
}

Eigen::Matrix3d randomMatrix(std::mt19937& rng, double scale) {
  return test::randomVectors<3>(rng, scale);
}

TEST(RotationExtraction, MethodNamesRoundTrip) {
  for (RotationMethod m :
       {RotationMethod::small, RotationMethod::large, RotationMethod::polar, RotationMethod::svd}) {
    EXPECT_EQ(parseRotationMethod(rotationMethodName(m)), m);
  }
  EXPECT_EQ(rotationMethodName(RotationMethod::polar), "polar");
  EXPECT_FALSE(parseRotationMethod("qr").has_value());
}

TEST(RotationExtraction, FrameFromEdgesIsGramSchmidt) {
  const Eigen::Vector3d a(2, 0.5, -1), b(0.3, 1.7, 0.4);
  const Eigen::Matrix3d N = computeFrameFromEdges(a, b);
  expectProperRotation(N);
  EXPECT_TRUE(N.col(0).isApprox(a.normalized()));
  EXPECT_NEAR(N.col(2).dot(b), 0, 1e-12);  // e2 in the plane (a, b)
  EXPECT_GT(N.col(1).dot(b), 0);           // on the side of b
  // Equivariance: rotating both edges rotates the frame.
  std::mt19937 rng(3);
  const Eigen::Matrix3d Q = randomRotation(rng);
  EXPECT_TRUE(computeFrameFromEdges(Q * a, Q * b).isApprox(Q * N, 1e-12));
}

TEST(RotationExtraction, FrameOfDegenerateEdgesIsStillARotation) {
  const Eigen::Vector3d a(1, 2, 3);
  expectProperRotation(computeFrameFromEdges(a, 2 * a));
  expectProperRotation(computeFrameFromEdges(a, Eigen::Vector3d::Zero()));
  EXPECT_TRUE(computeFrameFromEdges(Eigen::Vector3d::Zero(), a).isIdentity());
}

TEST(RotationExtraction, PolarRotationLeavesSymmetricPositiveStretch) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Matrix3d Q = randomRotation(rng);
    Eigen::Matrix3d S = randomMatrix(rng, 0.4);
    S = (Eigen::Matrix3d::Identity() + 0.5 * (S + S.transpose())).eval();
    const Eigen::Matrix3d F = Q * S;
    if (F.determinant() <= 0.1) continue;
    const Eigen::Matrix3d R = computePolarRotation(F);
    expectProperRotation(R);
    EXPECT_TRUE(R.isApprox(Q, 1e-12));
    const Eigen::Matrix3d stretch = R.transpose() * F;
    EXPECT_TRUE(stretch.isApprox(stretch.transpose(), 1e-12));
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(stretch).eigenvalues().minCoeff(), 0);
    // Without inversion, polar and SVD rotations agree.
    EXPECT_TRUE(computeSvdRotation(F).isApprox(R, 1e-12));
  }
}

TEST(RotationExtraction, PolarHandlesStrongStretchAndLargeScale) {
  const Eigen::Matrix3d F = Eigen::Vector3d(1e3, 1, 1e-3).asDiagonal();
  expectProperRotation(computePolarRotation(F));
  EXPECT_TRUE(computePolarRotation(F).isIdentity(1e-12));
}

TEST(RotationExtraction, InvertedGradientFlipsSmallestSingularAxis) {
  std::mt19937 rng(7);
  // F = Q diag(1.2, 0.9, -0.3) P^T: the smallest singular axis (P e3) is inverted.
  const Eigen::Matrix3d Q = randomRotation(rng), P = randomRotation(rng);
  const Eigen::Matrix3d F = Q * Eigen::Vector3d(1.2, 0.9, -0.3).asDiagonal() * P.transpose();
  for (const Eigen::Matrix3d& R : {computeSvdRotation(F), computePolarRotation(F)}) {
    expectProperRotation(R);
    EXPECT_TRUE(R.isApprox(Q * P.transpose(), 1e-12));
    const Eigen::Matrix3d stretch = R.transpose() * F;
    EXPECT_TRUE(stretch.isApprox(stretch.transpose(), 1e-12));
    const Eigen::Vector3d eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(stretch).eigenvalues();
    EXPECT_NEAR(eigenvalues[0], -0.3, 1e-12);
  }
}

TEST(RotationExtraction, FlatAndNonFiniteGradientsGiveRotations) {
  const Eigen::Matrix3d flat = Eigen::Vector3d(1, 1, 0).asDiagonal();
  expectProperRotation(computePolarRotation(flat));
  expectProperRotation(computeSvdRotation(flat));
  expectProperRotation(computeSvdRotation(Eigen::Matrix3d::Zero()));
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(computePolarRotation(nan).isIdentity());
}

TEST(RotationExtraction, RotationsAreEquivariant) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + randomMatrix(rng, 0.8);
    const Eigen::Matrix3d Q = randomRotation(rng);
    EXPECT_TRUE(computeSvdRotation(Q * F).isApprox(Q * computeSvdRotation(F), 1e-10));
    EXPECT_TRUE(computePolarRotation(Q * F).isApprox(Q * computePolarRotation(F), 1e-10));
  }
}

}  // namespace
}  // namespace stroma::fem
