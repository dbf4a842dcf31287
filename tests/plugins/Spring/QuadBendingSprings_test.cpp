// SPDX-License-Identifier: MIT
// QuadularBendingSprings and QuadBendingSprings: the springs across the edges shared by two
// quads (which pairs, how many, per edge or once), at rest on a flat grid, the closed-form force
// of a folded strip, the generic force-field test, and bad input.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

// 2 x 2 quads on a 3 x 3 grid of points (spacing 1): point i + 3 j at (i, j, 0).
const char* kGrid = "0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0  0 2 0  1 2 0  2 2 0";
const char* kQuads = "0 1 4 3  1 2 5 4  3 4 7 6  4 5 8 7";

std::string gridScene(const std::string& component, const std::string& position = kGrid) {
  return R"(<Node name="root" gravity="0 0 0">
  <MeshTopology quads=")" +
         std::string(kQuads) + R"("/>
  <MechanicalObject name="dofs" rest_position=")" +
         std::string(kGrid) + R"(" position=")" + position + R"("/>
  )" + component +
         R"(
</Node>)";
}

// The springs as sorted "a-b" pairs.
std::vector<std::string> pairsOf(SceneHolder& s) {
  const auto v = numbers(s.text("@springs.spring"));
  std::vector<std::string> pairs;
  for (std::size_t k = 0; k + 4 < v.size(); k += 5) {
    const int a = int(v[k]), b = int(v[k + 1]);
    pairs.push_back(std::to_string(std::min(a, b)) + "-" + std::to_string(std::max(a, b)));
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

TEST(QuadularBendingSprings, TwoSpringsAcrossEachInteriorEdge) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene(R"(<QuadularBendingSprings name="springs" stiffness="100"
      damping="0"/>)")));
  // Interior edges 1-4, 3-4, 4-5, 4-7; each gives the two grid lines across it. The lines
  // through the centre, 3-5 and 1-7, are crossed by two edges each: made twice, as SOFA does.
  EXPECT_EQ(pairsOf(s),
            (std::vector<std::string>{"0-2", "0-6", "1-7", "1-7", "2-8", "3-5", "3-5", "6-8"}));
  // Rest length 2 (the rest positions), stiffness as given (not per length).
  const auto v = numbers(s.text("@springs.spring"));
  EXPECT_EQ(v[2], 100);
  EXPECT_EQ(v[4], 2);
  ForceFieldChecker check(s.scene(), s.root());
  EXPECT_EQ(check.force().cwiseAbs().maxCoeff(), 0.0);  // flat grid: at rest
}

TEST(QuadBendingSprings, EachPairOnceAndRestLengthsFromThePositions) {
  SceneHolder s;
  // Positions folded along the line x = 1: the rest lengths are those of the positions.
  ASSERT_TRUE(
      s.load(gridScene(R"(<QuadBendingSprings name="springs" stiffness="100"
      damping="0"/>)",
                       "0 0 0.5  1 0 0  2 0 0  0 1 0.5  1 1 0  2 1 0  0 2 0.5  1 2 0  2 2 0")));
  EXPECT_EQ(pairsOf(s), (std::vector<std::string>{"0-2", "0-6", "1-7", "2-8", "3-5", "6-8"}));
  ForceFieldChecker check(s.scene(), s.root());
  EXPECT_EQ(check.force().cwiseAbs().maxCoeff(), 0.0);
  const auto v = numbers(s.text("@springs.spring"));
  for (std::size_t k = 0; k < v.size(); k += 5)
    if ((v[k] == 0 && v[k + 1] == 2) || (v[k] == 2 && v[k + 1] == 0))
      EXPECT_DOUBLE_EQ(v[k + 4], std::sqrt(4.25));
}

TEST(QuadularBendingSprings, FoldedStripGivesTheClosedFormForce) {
  // Three quads in a row; the first point lifted by h. Springs 0-2 (across edge 1-5), 4-6, 1-3,
  // 5-7 of rest length 2; only 0-2 is stretched: f0 = ks (l - 2) (x2 - x0) / l.
  const double h = 0.2;
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node name="root" gravity="0 0 0">
  <MeshTopology quads="0 1 5 4  1 2 6 5  2 3 7 6"/>
  <MechanicalObject name="dofs" rest_position="0 0 0  1 0 0  2 0 0  3 0 0  0 1 0  1 1 0  2 1 0  3 1 0"
      position="0 0 0.2  1 0 0  2 0 0  3 0 0  0 1 0  1 1 0  2 1 0  3 1 0"/>
  <QuadularBendingSprings name="springs" stiffness="100" damping="0"/>
</Node>)"));
  EXPECT_EQ(pairsOf(s), (std::vector<std::string>{"0-2", "1-3", "4-6", "5-7"}));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  const double l = std::sqrt(4 + h * h);
  const Vec3d f0 = 100 * (l - 2) * Vec3d(2, 0, -h) / l;
  EXPECT_LT((f.segment<3>(0) - f0).norm(), 1e-12);
  EXPECT_LT((f.segment<3>(6) + f0).norm(), 1e-12);
  EXPECT_NEAR(f.norm(), std::sqrt(2.0) * f0.norm(), 1e-12);
}

TEST(QuadularBendingSprings, PassesTheForceFieldTest) {
  checkForceField(gridScene(R"(<QuadularBendingSprings name="springs" stiffness="300"
      damping="2"/>)"),
                  {.rotationInvariant = true});
}

TEST(QuadBendingSprings, PassesTheForceFieldTest) {
  checkForceField(gridScene(R"(<QuadBendingSprings name="springs" stiffness="300" damping="2"/>)"),
                  {.rotationInvariant = true});
}

TEST(QuadBendingSprings, LocalRangeKeepsSpringsWithAPointInIt) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene(R"(<QuadBendingSprings name="springs" localRange="6 8"/>)")));
  EXPECT_EQ(pairsOf(s), (std::vector<std::string>{"6-8"}));
}

TEST(QuadularBendingSprings, BadInputIsReported) {
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(R"(<Node><MeshTopology triangles="0 1 2"/>
<MechanicalObject position="0 0 0  1 0 0  0 1 0"/><QuadularBendingSprings/></Node>)",
                            {"has no quads"})
                  .field,
              "topology");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(gridScene(R"(<QuadularBendingSprings damping="-1"/>)"), {}).field,
              "damping");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(R"(<Node><MeshTopology quads="0 1 4 3  1 2 5 4"/>
<MechanicalObject position="0 0 0  1 0 0  2 0 0  0 1 0"/><QuadBendingSprings/></Node>)",
                            {"out of range"})
                  .field,
              "topology");
  }
}

}  // namespace
}  // namespace stroma::test
