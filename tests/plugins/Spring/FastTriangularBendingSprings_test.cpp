// SPDX-License-Identifier: MIT
// FastTriangularBendingSprings: the linear bending energy of each pair of triangles (Volino and
// Magnenat-Thalmann 2006) in closed form on a folded pair, SOFA's forces on skewed pairs
// (measured with runSofa), zero force on a flat sheet, the generic force-field test, and bad
// input.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

std::string pairScene(const std::string& triangles, const std::string& rest,
                      const std::string& position, const std::string& stiffness) {
  return R"(<Node name="root" gravity="0 0 0">
  <MeshTopology triangles=")" +
         triangles + R"("/>
  <MechanicalObject name="dofs" rest_position=")" +
         rest + R"(" position=")" + position + R"("/>
  <FastTriangularBendingSprings name="bending" bendingStiffness=")" +
         stiffness + R"("/>
</Node>)";
}

TEST(FastTriangularBendingSprings, FoldedPairHasTheClosedFormEnergyAndForce) {
  // Edge 0-2 of length 2, opposite points 1 and 3 at heights 1: alpha = (-1, 1, -1, 1),
  // lambda = (2/3) B |e| / (H1 + H3) = (2/3) B. Lifting 1 by h and 3 by k gives R = (0, 0, h+k).
  const double B = 3, h = 0.3, k = 0.1;
  SceneHolder s;
  ASSERT_TRUE(s.load(pairScene("0 1 2  0 2 3", "0 0 0  1 -1 0  2 0 0  1 1 0",
                               "0 0 0  1 -1 0.3  2 0 0  1 1 0.1", "3")));
  ForceFieldChecker check(s.scene(), s.root());
  const double lambda = 2.0 / 3.0 * B, R = h + k;
  EXPECT_NEAR(check.energy(), 0.5 * lambda * R * R, 1e-14);
  const Eigen::VectorXd f = check.force();
  for (int i = 0; i < 4; ++i) {
    const double alpha = i % 2 ? 1 : -1;
    EXPECT_NEAR(f[3 * i + 2], -lambda * alpha * R, 1e-14) << i;
    EXPECT_EQ(f[3 * i], 0.0);
    EXPECT_EQ(f[3 * i + 1], 0.0);
  }
}

// SOFA (runSofa, one explicit step of unit masses, dt = 1): the forces on pairs that are skewed,
// of other sizes, and curved at rest (SOFA pulls those flat too).
TEST(FastTriangularBendingSprings, MatchesSofa) {
  struct Case {
    const char *triangles, *rest, *position, *stiffness;
    std::array<double, 12> sofa;
  };
  // clang-format off
  const Case cases[] = {
      {"0 1 2  0 2 3", "0 0 0  0.5 -1 0  2 0 0  1.5 2 0", "0 0 0  0.5 -1 0.3  2 0 0  1.5 2 0.1", "1",
       {0, 0, 0.136111, 0, 0, -0.155556, 0, 0, 0.0972222, 0, 0, -0.0777778}},
      {"0 1 2  2 3 0", "0 0 0  0.7 -1 0  3 0 0  2.2 0.5 0",
       "0.1 0 0  0.7 -1 0.3  3 0.1 0  2.2 0.5 -0.2", "2",
       {-0.450667, -0.589333, -0.346667, 0.346667, 0.453333, 0.266667,
        -0.589333, -0.770667, -0.453333, 0.693333, 0.906667, 0.533333}},
      {"0 1 2  0 2 3", "0 0 0  1 -1 0.3  2 0 0  1 1 0.1", "0 0 0  1 -1 0.3  2 0 0  1 1 0.1", "1",
       {0, 0.0236431, 0.245798, 0, -0.0231926, -0.241115,
        0, 0.0236431, 0.245798, 0, -0.0240936, -0.250482}}};
  // clang-format on
  for (const Case& c : cases) {
    SceneHolder s;
    ASSERT_TRUE(s.load(pairScene(c.triangles, c.rest, c.position, c.stiffness)));
    ForceFieldChecker check(s.scene(), s.root());
    const Eigen::VectorXd f = check.force();
    // SOFA prints 6 significant digits.
    for (int i = 0; i < 12; ++i)
      EXPECT_NEAR(f[i], c.sofa[i], 5e-6 * std::abs(c.sofa[i]) + 1e-9) << c.rest << " " << i;
  }
}

TEST(FastTriangularBendingSprings, FlatSheetIsAtRest) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node name="root" gravity="0 0 0">
  <RegularGridTopology name="grid" n="4 3 1" min="0 0 0" max="3 1 0"/>
  <MechanicalObject name="dofs" position="@grid.position"/>
  <FastTriangularBendingSprings name="bending" bendingStiffness="50"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  EXPECT_LT(check.force().cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT(check.energy(), 1e-26);
  // Lifting an inside point bends the pairs around it.
  check.shift(3 * 5 + 2, 0.1);
  EXPECT_GT(check.energy(), 1e-3);
}

TEST(FastTriangularBendingSprings, PassesTheForceFieldTest) {
  checkForceField(R"(<Node name="root" gravity="0 0 0">
  <MeshTopology triangles="0 1 4  0 4 3  1 2 5  1 5 4  3 4 7  3 7 6  4 5 8  4 8 7"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  0 1 0  1.1 1.2 0  2 1 0
                                           0 2 0  1 2 0  2 2 0"/>
  <FastTriangularBendingSprings name="bending" bendingStiffness="20"/>
</Node>)",
                  {.rotationInvariant = true});
}

TEST(FastTriangularBendingSprings, BadInputIsReported) {
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(pairScene("0 1 2  0 2 3", "0 0 0  1 0 0  2 0 0  1 1 0",
                                      "0 0 0  1 0 0  2 0 0  1 1 0", "1"),
                            {"degenerate", "around the edges 2-0"})
                  .field,
              "topology");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(pairScene("0 1 2  0 2 3", "0 0 0  1 -1 0  2 0 0  1 1 0",
                                      "0 0 0  1 -1 0  2 0 0  1 1 0", "-2"),
                            {})
                  .field,
              "bendingStiffness");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(R"(<Node><MeshTopology quads="0 1 2 3"/>
<MechanicalObject position="0 0 0  1 0 0  1 1 0  0 1 0"/><FastTriangularBendingSprings/></Node>)",
                            {"has no triangles"})
                  .field,
              "topology");
  }
}

}  // namespace
}  // namespace stroma::test
