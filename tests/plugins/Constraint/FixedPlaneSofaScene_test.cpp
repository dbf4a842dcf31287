// SPDX-License-Identifier: MIT
// SOFA's FixedPlaneProjectiveConstraint.scn (a liver with the points of a slab along z kept in
// their planes, hanging from a BoxConstraint, with its collision pipeline) runs unmodified and
// follows SOFA's trajectory: after 100 steps (2 s) the positions are within 2e-5 of SOFA's
// (sofa-fixed-plane-liver-positions.txt, from scripts/make-sofa-references.sh;
// measured 5e-6 per coordinate, SOFA's file keeping 6 significant digits), the liver having
// moved by 0.15 (more than 0.1 asserted).
#include <gtest/gtest.h>

#include <cstdio>

#include "scenes/SofaReference.h"

namespace stroma::test {
namespace {

TEST(FixedPlaneSofaScene, FollowsSofasTrajectory) {
  const SofaComparison c = compareWithSofa(
      "Component/Constraint/Projective/FixedPlaneProjectiveConstraint.scn", "/root/Liver/dofs", 100,
      "tests/plugins/Constraint/sofa-fixed-plane-liver-positions.txt", {"Collision"});
  if (!c.skipped.empty()) GTEST_SKIP() << c.skipped;
  EXPECT_GE(c.difference, 0);
  EXPECT_LT(c.difference, 2e-5);
  EXPECT_GT(c.moved, 0.1);
  std::printf("[ sofa ] after 100 steps, %.2g from SOFA's positions (moved %.2g)\n", c.difference,
              c.moved);
}

}  // namespace
}  // namespace stroma::test
