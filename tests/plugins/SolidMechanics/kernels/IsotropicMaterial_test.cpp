// SPDX-License-Identifier: MIT
// Lame parameters and the Voigt elasticity matrix against hand formulas.
#include "SolidMechanics/kernels/IsotropicMaterial.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <limits>

namespace stroma::fem {
namespace {

TEST(IsotropicMaterial, LameParametersMatchHandValues) {
  // E = 1000, nu = 0.25: lambda = 250 / (1.25 * 0.5) = 400, mu = 1000 / 2.5 = 400.
  const LameParameters a = computeLameParameters(1000, 0.25);
  EXPECT_DOUBLE_EQ(a.lambda, 400);
  EXPECT_DOUBLE_EQ(a.mu, 400);
  // E = 5000, nu = 0.45: lambda = 2250 / (1.45 * 0.1) = 15517.24..., mu = 5000 / 2.9.
  const LameParameters b = computeLameParameters(5000, 0.45);
  EXPECT_NEAR(b.lambda, 15517.241379310345, 1e-9);
  EXPECT_NEAR(b.mu, 1724.1379310344828, 1e-9);
  // nu = 0: no lateral coupling, mu = E / 2.
  const LameParameters c = computeLameParameters(2, 0);
  EXPECT_DOUBLE_EQ(c.lambda, 0);
  EXPECT_DOUBLE_EQ(c.mu, 1);
}

TEST(IsotropicMaterial, ValidRangeIsOpenInterval) {
  EXPECT_TRUE(isValidIsotropicMaterial(1, 0.3));
  EXPECT_TRUE(isValidIsotropicMaterial(1, -0.99));
  EXPECT_TRUE(isValidIsotropicMaterial(1, 0.4999));
  EXPECT_FALSE(isValidIsotropicMaterial(0, 0.3));
  EXPECT_FALSE(isValidIsotropicMaterial(-1, 0.3));
  EXPECT_FALSE(isValidIsotropicMaterial(1, 0.5));
  EXPECT_FALSE(isValidIsotropicMaterial(1, -1));
  EXPECT_FALSE(isValidIsotropicMaterial(std::numeric_limits<double>::quiet_NaN(), 0.3));
  EXPECT_FALSE(isValidIsotropicMaterial(1, std::numeric_limits<double>::infinity()));
}

TEST(IsotropicMaterial, ElasticityMatrixEntries) {
  const Matrix6d C = computeElasticityMatrix({400, 300});
  Matrix6d expected = Matrix6d::Zero();
  // clang-format off
  expected.topLeftCorner<3, 3>() << 1000, 400, 400,
                                     400, 1000, 400,
                                     400, 400, 1000;
  // clang-format on
  expected.bottomRightCorner<3, 3>() = 300 * Eigen::Matrix3d::Identity();
  EXPECT_EQ(C, expected);
}

TEST(IsotropicMaterial, ComplianceGivesYoungModulusPoissonRatioAndShearModulus) {
  const double E = 2.5e5, nu = 0.35;
  const Matrix6d C = computeElasticityMatrix(computeLameParameters(E, nu));
  EXPECT_TRUE(C.isApprox(C.transpose()));
  EXPECT_EQ(Eigen::LLT<Matrix6d>(C).info(), Eigen::Success);  // positive definite
  const Matrix6d S = C.inverse();
  // Uniaxial stress sigma_xx = 1: eps_xx = 1/E, lateral eps = -nu/E.
  EXPECT_NEAR(S(0, 0) * E, 1, 1e-12);
  EXPECT_NEAR(S(1, 0) * E, -nu, 1e-12);
  EXPECT_NEAR(S(2, 0) * E, -nu, 1e-12);
  // Shear tau_xy = 1: engineering strain gamma_xy = 1/G, G = E / (2 (1 + nu)).
  EXPECT_NEAR(S(3, 3) * E / (2 * (1 + nu)), 1, 1e-12);
  // Hydrostatic pressure: volumetric strain p / K, K = E / (3 (1 - 2 nu)).
  const Vector6d pressure = (Vector6d() << 1, 1, 1, 0, 0, 0).finished();
  EXPECT_NEAR((S * pressure).head<3>().sum() * E / (3 * (1 - 2 * nu)), 1, 1e-12);
}

}  // namespace
}  // namespace stroma::fem
