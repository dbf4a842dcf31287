// SPDX-License-Identifier: MIT
// BoxConstraint: the points inside its boxes (selected on the rest positions, faces included)
// stay while the others fall; the selection follows a change of `box`; the assembled rows; a
// box with min > max is an error naming the field and the box.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma::test {
namespace {

const char* kSolver = R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>)";

// Five free points (no force between them), unit masses, gravity along -y.
std::string scene(const std::string& constraint, const std::string& restPosition = "") {
  return std::string(R"(<Node name="root" gravity="0 -10 0" dt="0.01">)") + kSolver + R"(
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0" )" +
         restPosition +
         R"(/>
  <UniformMass vertexMass="1"/>
  )" + constraint +
         "\n</Node>";
}

/// The y of each point.
std::vector<double> heights(SceneHolder& s) {
  const auto x = numbers(s.text("@dofs.position"));
  std::vector<double> y;
  for (std::size_t i = 1; i < x.size(); i += 3) y.push_back(x[i]);
  return y;
}

TEST(BoxConstraint, PointsInsideEitherBoxStayTheOthersFall) {
  SceneHolder s;
  // Box 0 holds point 0 on its face x = 0; box 1 holds points 3 and 4 (4 on its corner).
  ASSERT_TRUE(s.load(scene(R"(<BoxConstraint name="box" box="0 -1 -1 0.5 1 1  2.5 -1 -1 4 0 0"
                                drawBoxes="1"/>)")));
  EXPECT_EQ(s.text("@box.indices"), "0 3 4");
  const int n = 10;
  ASSERT_TRUE(s.step(n));
  const double fall = -10 * 1e-4 * n * (n + 1) / 2;  // implicit Euler, free fall
  const auto y = heights(s);
  EXPECT_EQ(y[0], 0);
  EXPECT_EQ(y[3], 0);
  EXPECT_EQ(y[4], 0);
  EXPECT_NEAR(y[1], fall, 1e-12);
  EXPECT_NEAR(y[2], fall, 1e-12);
  std::vector<std::size_t> rows;
  s.get<BaseProjectiveConstraint>("@box")->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{0, 1, 2, 9, 10, 11, 12, 13, 14}));
}

TEST(BoxConstraint, SelectsOnTheRestPositions) {
  SceneHolder s;
  // Point 1 rests at x = 1 (outside) but starts at x = 0.2 (inside); point 2 the reverse.
  ASSERT_TRUE(s.load(scene(R"(<BoxConstraint name="box" box="1.5 -1 -1 2.5 1 1"/>)",
                           R"(rest_position="0 0 0  0.2 0 0  2 0 0  3 0 0  4 0 0")")));
  EXPECT_EQ(s.text("@box.indices"), "2");
}

TEST(BoxConstraint, ChangingTheBoxChangesTheFixedPoints) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(R"(<BoxConstraint name="box" box="-0.5 -1 -1 1.5 1 1"/>)")));
  ASSERT_TRUE(s.step(5));
  auto y = heights(s);
  EXPECT_EQ(y[0], 0);
  EXPECT_EQ(y[1], 0);
  EXPECT_LT(y[2], -1e-3);
  // Now the box holds points 2 to 4 only: 0 and 1 are released, 2 to 4 stop where they are.
  s.set("@box.box", "1.5 -1 -1 4.5 1 1");
  const std::vector<double> before = y;
  ASSERT_TRUE(s.step(5));
  EXPECT_EQ(s.text("@box.indices"), "2 3 4");
  y = heights(s);
  EXPECT_LT(y[0], -1e-3);
  EXPECT_LT(y[1], -1e-3);
  for (int i = 2; i < 5; ++i) EXPECT_EQ(y[i], before[i]) << i;
}

TEST(BoxConstraint, MinAboveMaxIsAnErrorNamingTheBox) {
  SceneHolder s;
  const Message m = s.loadFailing(scene(R"(<BoxConstraint box="0 0 0 1 1 1  0 2 0 1 1 1"/>)"),
                                  {"box 1 has min > max along y"});
  EXPECT_EQ(m.field, "box");
  EXPECT_EQ(m.componentClass, "BoxConstraint");
}

TEST(BoxConstraint, NoBoxIsAWarning) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene("<BoxConstraint name=\"box\"/>"), /*allowWarnings=*/true));
  bool warned = false;
  for (const Message& m : s.scene().log().messages())
    warned |= m.level == MessageLevel::warning && m.field == "box";
  EXPECT_TRUE(warned);
  EXPECT_EQ(s.text("@box.indices"), "");
}

}  // namespace
}  // namespace stroma::test
