// SPDX-License-Identifier: MIT
// Uniaxial stress of a block against ../shared/REFERENCES.md; small-strain limits agree with
// linear elasticity; the lateral stress is zero (checked from the stress formula); the inverse
// (stretch for a stress) returns the stretch.
#include "Validation/kernels/UniaxialStretch.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

namespace stroma::reference {
namespace {

UniaxialStretch make(UniaxialMaterial m, double nu, double E = 1) {
  UniaxialStretch u;
  u.material = m;
  u.youngModulus = E;
  u.poissonRatio = nu;
  return u;
}

TEST(UniaxialStretch, StVenantKirchhoffMatchesReferenceValues) {
  const UniaxialStretch s = make(UniaxialMaterial::stVenantKirchhoff, 0.3);
  const double expected[][2] = {{0.5, -0.18750}, {0.7, -0.17850}, {0.9, -0.08550},
                                {1.1, 0.11550},  {1.3, 0.44850},  {1.5, 0.93750}};
  for (const auto& e : expected) EXPECT_NEAR(s.nominalStress(e[0]), e[1], 1e-12) << e[0];
  EXPECT_NEAR(s.lateralStretch(1.5), std::sqrt(1 - 0.3 * 1.25), 1e-15);
  // Minimum of P at 1/sqrt(3): -E / (3 sqrt 3).
  EXPECT_NEAR(s.nominalStress(1 / std::sqrt(3.0)), -0.19245, 1e-5);
  EXPECT_TRUE(std::isnan(s.stretchForNominalStress(-0.2)));
}

TEST(UniaxialStretch, NeoHookeanMatchesReferenceValues) {
  // REFERENCES.md, E = 1: {nu, lambda, t, P}.
  const double expected[][4] = {
      {0.3, 0.8, 1.06734, -0.24001},  {0.3, 1.2, 0.94563, 0.17493},  {0.3, 1.5, 0.88017, 0.37828},
      {0.45, 0.8, 1.10446, -0.24993}, {0.45, 1.2, 0.92063, 0.17024}, {0.45, 1.5, 0.83068, 0.35861},
      {0.49, 0.8, 1.11526, -0.25327}, {0.49, 1.2, 0.91440, 0.16887}, {0.49, 1.5, 0.81924, 0.35321}};
  for (const auto& e : expected) {
    const UniaxialStretch s = make(UniaxialMaterial::neoHookean, e[0]);
    EXPECT_NEAR(s.lateralStretch(e[1]), e[2], 5e-6) << "nu " << e[0] << " lambda " << e[1];
    EXPECT_NEAR(s.nominalStress(e[1]), e[3], 5e-6) << "nu " << e[0] << " lambda " << e[1];
  }
}

TEST(UniaxialStretch, LateralStressIsZero) {
  // Neo-Hookean first Piola P = mu (F - F^-T) + lambda_L ln J F^-T at F = diag(lambda, t, t):
  // its lateral entries vanish at the computed t (the 1-D root find converged).
  for (double nu : {0.0, 0.3, 0.49, 0.4999}) {
    const double E = 2e3, lambdaL = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    const UniaxialStretch s = make(UniaxialMaterial::neoHookean, nu, E);
    for (double stretch : {0.3, 0.8, 1.0, 1.7, 4.0}) {
      const double t = s.lateralStretch(stretch);
      const Eigen::Matrix3d F = Eigen::Vector3d(stretch, t, t).asDiagonal();
      const Eigen::Matrix3d Finv = F.inverse().transpose();
      const Eigen::Matrix3d P = mu * (F - Finv) + lambdaL * std::log(F.determinant()) * Finv;
      EXPECT_NEAR(P(1, 1), 0, 1e-10 * E) << nu << " " << stretch;
      EXPECT_NEAR(P(0, 0), s.nominalStress(stretch), 1e-10 * E);
    }
  }
}

TEST(UniaxialStretch, SmallStrainLimitIsLinear) {
  // Every material has E and nu as its small-strain constants: at lambda = 1 + eps the stress
  // is E eps and the lateral strain -nu eps, up to O(eps^2).
  for (UniaxialMaterial m : {UniaxialMaterial::linear, UniaxialMaterial::stVenantKirchhoff,
                             UniaxialMaterial::neoHookean}) {
    const UniaxialStretch s = make(m, 0.35, 5e3);
    for (double eps : {1e-4, -1e-4}) {
      EXPECT_NEAR(s.nominalStress(1 + eps) / (5e3 * eps), 1, 5e-4);
      EXPECT_NEAR((s.lateralStretch(1 + eps) - 1) / eps, -0.35, 5e-4);
    }
  }
}

TEST(UniaxialStretch, StretchForNominalStressInverts) {
  for (UniaxialMaterial m : {UniaxialMaterial::linear, UniaxialMaterial::stVenantKirchhoff,
                             UniaxialMaterial::neoHookean})
    for (double stretch : {0.7, 0.95, 1.05, 1.4}) {
      const UniaxialStretch s = make(m, 0.3, 10);
      EXPECT_NEAR(s.stretchForNominalStress(s.nominalStress(stretch)), stretch, 1e-12);
    }
}

TEST(UniaxialStretch, DisplacementIsHomogeneous) {
  const UniaxialStretch s = make(UniaxialMaterial::linear, 0.25);
  const Eigen::Vector3d origin(1, 2, 3), axis(0, 0, 1);
  const Eigen::Vector3d u = s.displacement(Eigen::Vector3d(2, 2, 5), origin, axis, 1.1);
  EXPECT_NEAR(u.z(), 0.2, 1e-15);
  EXPECT_NEAR(u.x(), -0.025, 1e-15);
  EXPECT_NEAR(u.y(), 0, 1e-15);
}

}  // namespace
}  // namespace stroma::reference
