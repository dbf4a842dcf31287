// SPDX-License-Identifier: MIT
// The projector kernel of the plane, line and point constraints, alone: P is symmetric and
// idempotent, P v lies in the allowed subspace and v - P v is orthogonal to it; positions land
// on the affine set; fixed rows are offered exactly when P is diagonal.
#include "../../../plugins/Constraint/src/AllowedMotion.h"

#include <gtest/gtest.h>

#include <random>

namespace stroma::constraint {
namespace {

Vec3d randomVector(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  return {u(rng), u(rng), u(rng)};
}

TEST(AllowedMotion, ProjectorsAreOrthogonalAndIdempotent) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    Vec3d n;
    ASSERT_TRUE(unitVector(randomVector(rng), n));
    for (const AllowedMotion& m :
         {AllowedMotion::inPlane(n), AllowedMotion::alongLine(n), AllowedMotion::none()}) {
      EXPECT_LT((m.P - m.P.transpose()).norm(), 1e-15);  // symmetric
      EXPECT_LT((m.P * m.P - m.P).norm(), 1e-15);        // idempotent
      const Vec3d v = randomVector(rng);
      const Vec3d Pv = m.project(v);
      EXPECT_LT((m.project(Pv) - Pv).norm(), 1e-15);
      EXPECT_LT(std::abs((v - Pv).dot(Pv)), 1e-15);  // the removed part is orthogonal
    }
    const Vec3d v = randomVector(rng);
    EXPECT_LT(std::abs(n.dot(AllowedMotion::inPlane(n).project(v))), 1e-15);   // in the plane
    EXPECT_LT(n.cross(AllowedMotion::alongLine(n).project(v)).norm(), 1e-15);  // on the line
    EXPECT_EQ(AllowedMotion::none().project(v), Vec3d::Zero());
    // Positions: on the plane through o, the nearest point (x - p is along n).
    const Vec3d o = randomVector(rng), x = randomVector(rng);
    const Vec3d p = AllowedMotion::inPlane(n).projectPosition(x, o);
    EXPECT_LT(std::abs(n.dot(p - o)), 1e-15);
    EXPECT_LT(n.cross(x - p).norm(), 1e-15);
    const Vec3d q = AllowedMotion::alongLine(n).projectPosition(x, o);
    EXPECT_LT(n.cross(q - o).norm(), 1e-15);
    EXPECT_LT(std::abs(n.dot(x - q)), 1e-15);
  }
}

TEST(AllowedMotion, FixedAxesOnlyForAxisAlignedProjectors) {
  std::array<bool, 3> fixed{};
  ASSERT_TRUE(AllowedMotion::inPlane(Vec3d(0, 1, 0)).fixedAxes(fixed));
  EXPECT_EQ(fixed, (std::array<bool, 3>{false, true, false}));
  ASSERT_TRUE(AllowedMotion::alongLine(Vec3d(0, 0, -1)).fixedAxes(fixed));
  EXPECT_EQ(fixed, (std::array<bool, 3>{true, true, false}));
  ASSERT_TRUE(AllowedMotion::none().fixedAxes(fixed));
  EXPECT_EQ(fixed, (std::array<bool, 3>{true, true, true}));
  Vec3d n;
  ASSERT_TRUE(unitVector(Vec3d(1, 1, 0), n));
  EXPECT_FALSE(AllowedMotion::inPlane(n).fixedAxes(fixed));
  EXPECT_FALSE(AllowedMotion::alongLine(n).fixedAxes(fixed));
  EXPECT_FALSE(unitVector(Vec3d::Zero(), n));
}

}  // namespace
}  // namespace stroma::constraint
