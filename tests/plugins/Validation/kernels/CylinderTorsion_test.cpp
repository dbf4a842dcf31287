// SPDX-License-Identifier: MIT
// Torsion of a circular cylinder: twist angle against a hand value, and the displacement field
// is a rigid rotation of each section (no stretch, no axial motion).
#include "Validation/kernels/CylinderTorsion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "Validation/kernels/AffinePatch.h"

namespace stroma::reference {
namespace {

TEST(CylinderTorsion, TwistAngleMatchesHandValue) {
  CylinderTorsion c;  // R = 0.1, L = 1, T = 1, E = 1e6, nu = 0.3
  // G = 1e6 / 2.6 = 384615.38, J = pi 1e-4 / 2 = 1.5708e-4: phi(L) = 1 / 60.415 = 0.016552.
  EXPECT_NEAR(c.polarMomentOfArea(), std::numbers::pi * 1e-4 / 2, 1e-18);
  EXPECT_NEAR(c.twistAngle(1), 2.6 / (std::numbers::pi * 1e-4 / 2) * 1e-6, 1e-15);
  EXPECT_NEAR(c.twistAngle(1), 0.0165521, 1e-7);
  EXPECT_NEAR(c.twistAngle(0.5), c.twistAngle(1) / 2, 1e-15);
  EXPECT_EQ(c.twistAngle(-1), 0);
}

TEST(CylinderTorsion, SectionsTurnRigidly) {
  CylinderTorsion c;
  const Eigen::Vector3d origin(0, 0, 0), axis(1, 0, 0);
  const Eigen::Vector3d X(0.8, 0.06, -0.08);
  const Eigen::Vector3d u = c.displacement(X, origin, axis);
  EXPECT_NEAR(u.x(), 0, 0);
  EXPECT_NEAR(u.dot(X - Eigen::Vector3d(0.8, 0, 0)), 0, 1e-18);  // tangential
  EXPECT_NEAR(u.norm(), c.twistAngle(0.8) * 0.1, 1e-15);         // phi r
}

TEST(AffinePatch, MacNealHarderStrains) {
  const AffinePatch p = AffinePatch::macNealHarder();
  const Eigen::Matrix3d e = p.strain();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(e(i, i), 1e-3, 1e-18);
  EXPECT_NEAR(2 * e(0, 1), 1e-3, 1e-18);  // engineering shear
  // REFERENCES.md boundary field: u = 1e-3 (2x + y + z) / 2 at (0.249, 0.342, 0.192).
  const Eigen::Vector3d X(0.249, 0.342, 0.192);
  EXPECT_NEAR(p.displacement(X).x(), 1e-3 * (2 * 0.249 + 0.342 + 0.192) / 2, 1e-18);
}

}  // namespace
}  // namespace stroma::reference
