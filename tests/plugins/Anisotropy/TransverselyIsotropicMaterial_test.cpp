// SPDX-License-Identifier: MIT
// The transversely isotropic material (TransverselyIsotropicMaterial.h): the closed-form
// conversion from engineering constants to Spencer's parameters against the inverse of the
// compliance, the Voigt matrix of the reinforcement against the energy written term by term,
// and the positive-definiteness conditions against the eigenvalues of the compliance.
#include "Anisotropy/kernels/TransverselyIsotropicMaterial.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <random>

#include "SolidMechanics/kernels/IsotropicMaterial.h"

namespace stroma::anisotropy {
namespace {

// A fiber-reinforced soft tissue (fibers 6 times stiffer), a stiff composite, and a material
// with negative nu_TT.
const EngineeringConstants kMaterials[] = {{.youngModulusL = 30e3,
                                            .youngModulusT = 5e3,
                                            .poissonRatioLT = 0.35,
                                            .poissonRatioTT = 0.45,
                                            .shearModulusLT = 4e3},
                                           {.youngModulusL = 140e9,
                                            .youngModulusT = 10e9,
                                            .poissonRatioLT = 0.3,
                                            .poissonRatioTT = 0.4,
                                            .shearModulusLT = 5e9},
                                           {.youngModulusL = 2e3,
                                            .youngModulusT = 8e3,
                                            .poissonRatioLT = 0.1,
                                            .poissonRatioTT = -0.3,
                                            .shearModulusLT = 1.5e3}};

/// The compliance S (Voigt, engineering shear) of the constants with the fiber along x.
Matrix6d compliance(const EngineeringConstants& c) {
  Matrix6d S = Matrix6d::Zero();
  S(0, 0) = 1 / c.youngModulusL;
  S(1, 1) = S(2, 2) = 1 / c.youngModulusT;
  S(0, 1) = S(1, 0) = S(0, 2) = S(2, 0) = -c.poissonRatioLT / c.youngModulusL;
  S(1, 2) = S(2, 1) = -c.poissonRatioTT / c.youngModulusT;
  S(3, 3) = S(5, 5) = 1 / c.shearModulusLT;                // xy, zx: planes with x
  S(4, 4) = 2 * (1 + c.poissonRatioTT) / c.youngModulusT;  // yz: across the fiber
  return S;
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(TransverselyIsotropicMaterial, ClosedFormsInvertTheCompliance) {
  for (const EngineeringConstants& c : kMaterials) {
    ASSERT_EQ(checkEngineeringConstants(c), ConstantsStatus::ok);
    const SpencerParameters p = computeSpencerParameters(c);
    const Matrix6d C = computeTransverselyIsotropicElasticity(Eigen::Vector3d::UnitX(), p);
    const Matrix6d expected = compliance(c).inverse();
    EXPECT_LT((C - expected).norm(), 1e-13 * expected.norm()) << "E_L " << c.youngModulusL;
    // And back, through the numerical inverse.
    const EngineeringConstants back = computeEngineeringConstants(p);
    EXPECT_LT(relative(back.youngModulusL, c.youngModulusL), 1e-12);
    EXPECT_LT(relative(back.youngModulusT, c.youngModulusT), 1e-12);
    EXPECT_LT(relative(back.poissonRatioLT, c.poissonRatioLT), 1e-12);
    EXPECT_LT(relative(back.poissonRatioTT, c.poissonRatioTT), 1e-12);
    EXPECT_LT(relative(back.shearModulusLT, c.shearModulusLT), 1e-12);
  }
}

TEST(TransverselyIsotropicMaterial, TissueValuesAsPrintedInTheReadme) {
  // The README's example: E_L = 30 kPa, E_T = 5 kPa, nu_LT = 0.35, nu_TT = 0.45, G_LT = 4 kPa.
  const SpencerParameters p = computeSpencerParameters(kMaterials[0]);
  const IsotropicConstants iso = computeIsotropicConstants(p.lambda, p.muT);
  std::printf(
      "[ material ] lambda %.6g mu_T %.6g alpha %.6g beta %.6g mu_L %.6g; "
      "isotropic E %.6g nu %.6g\n",
      p.lambda, p.muT, p.alpha, p.beta, p.muL, iso.youngModulus, iso.poissonRatio);
  EXPECT_NEAR(p.muT, 5e3 / 2.9, 1e-9);
  EXPECT_NEAR(iso.youngModulus, 4566.98, 0.01);
  EXPECT_NEAR(iso.poissonRatio, 0.324425, 1e-6);
}

TEST(TransverselyIsotropicMaterial, IsotropicConstantsGiveNoReinforcement) {
  const double E = 3000, nu = 0.4;
  const SpencerParameters p = computeSpencerParameters({.youngModulusL = E,
                                                        .youngModulusT = E,
                                                        .poissonRatioLT = nu,
                                                        .poissonRatioTT = nu,
                                                        .shearModulusLT = E / (2 * (1 + nu))});
  const fem::LameParameters lame = fem::computeLameParameters(E, nu);
  EXPECT_NEAR(p.lambda, lame.lambda, 1e-12 * lame.lambda);
  EXPECT_NEAR(p.muT, lame.mu, 1e-12 * lame.mu);
  EXPECT_NEAR(p.muL, lame.mu, 1e-12 * lame.mu);
  EXPECT_NEAR(p.alpha, 0, 1e-12 * lame.lambda);
  EXPECT_NEAR(p.beta, 0, 1e-12 * lame.lambda);
  const IsotropicConstants iso = computeIsotropicConstants(p.lambda, p.muT);
  EXPECT_NEAR(iso.youngModulus, E, 1e-12 * E);
  EXPECT_NEAR(iso.poissonRatio, nu, 1e-14);
}

TEST(TransverselyIsotropicMaterial, VoigtMatrixGivesTheEnergyTermByTerm) {
  // W_r = 1/2 eps_v^T C_r eps_v (engineering shear) for random strains and fiber directions.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int sample = 0; sample < 20; ++sample) {
    Eigen::Matrix3d e;
    for (int i = 0; i < 9; ++i) e(i) = uniform(rng);
    e = 0.5 * (e + e.transpose()).eval();
    const Eigen::Vector3d a =
        Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized();
    const double alpha = 700 * uniform(rng), beta = 5000 * uniform(rng), muL = 4000, muT = 1700;
    fem::Vector6d v;
    v << e(0, 0), e(1, 1), e(2, 2), 2 * e(0, 1), 2 * e(1, 2), 2 * e(2, 0);
    const Matrix6d C = computeReinforcementElasticity(a, alpha, beta, muL, muT);
    const double W = computeReinforcementEnergyDensity(e, a, alpha, beta, muL, muT);
    EXPECT_NEAR(0.5 * v.dot(C * v), W, 1e-12 * (std::abs(W) + C.norm()));
    EXPECT_LT((C - C.transpose()).norm(), 1e-15 * C.norm());
  }
}

TEST(TransverselyIsotropicMaterial, ValidExactlyWhenTheComplianceIsPositiveDefinite) {
  // checkEngineeringConstants's conditions against the eigenvalues of S, on random constants
  // around the limits.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> ratio(-1.5, 1.5), modulus(0.1, 10);
  int valid = 0, invalid = 0;
  for (int sample = 0; sample < 2000; ++sample) {
    const EngineeringConstants c{.youngModulusL = modulus(rng),
                                 .youngModulusT = modulus(rng),
                                 .poissonRatioLT = ratio(rng),
                                 .poissonRatioTT = ratio(rng),
                                 .shearModulusLT = modulus(rng)};
    const double smallest =
        Eigen::SelfAdjointEigenSolver<Matrix6d>(compliance(c)).eigenvalues().minCoeff();
    const bool ok = checkEngineeringConstants(c) == ConstantsStatus::ok;
    EXPECT_EQ(ok, smallest > 0) << "nu_LT " << c.poissonRatioLT << " nu_TT " << c.poissonRatioTT;
    if (ok) {
      // Then C is positive definite too.
      const Matrix6d C = computeTransverselyIsotropicElasticity(Eigen::Vector3d::UnitX(),
                                                                computeSpencerParameters(c));
      EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix6d>(C).eigenvalues().minCoeff(), 0);
    }
    (ok ? valid : invalid)++;
  }
  EXPECT_GT(valid, 200);
  EXPECT_GT(invalid, 200);
  // Non-positive moduli and the bounds of nu_TT.
  EngineeringConstants c = kMaterials[0];
  c.youngModulusL = 0;
  EXPECT_EQ(checkEngineeringConstants(c), ConstantsStatus::youngModulusL);
  c = kMaterials[0];
  c.youngModulusT = -1;
  EXPECT_EQ(checkEngineeringConstants(c), ConstantsStatus::youngModulusT);
  c = kMaterials[0];
  c.shearModulusLT = 0;
  EXPECT_EQ(checkEngineeringConstants(c), ConstantsStatus::shearModulusLT);
  c = kMaterials[0];
  c.poissonRatioTT = 1;
  EXPECT_EQ(checkEngineeringConstants(c), ConstantsStatus::poissonRatioTT);
  c = kMaterials[0];
  c.poissonRatioLT = 1.3;  // 1.69 > (1 - 0.45) 30 / 10 = 1.65
  EXPECT_EQ(checkEngineeringConstants(c), ConstantsStatus::poissonRatioLT);
}

}  // namespace
}  // namespace stroma::anisotropy
