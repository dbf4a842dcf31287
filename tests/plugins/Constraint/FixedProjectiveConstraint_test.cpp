// SPDX-License-Identifier: MIT
// FixedProjectiveConstraint and PartialFixedProjectiveConstraint, for points and rigid frames:
// what stays, what moves, the assembled rows, and bad input.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma::test {
namespace {

const char* kSolver = R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>)";

TEST(FixedProjectiveConstraint, RigidFrameStaysUnderGravityAndSpin) {
  SceneHolder s;
  ASSERT_TRUE(
      s.load(std::string(R"(<Node name="root" gravity="0 -10 0" dt="0.01">)") + kSolver + R"(
  <MechanicalObject template="Rigid3" name="frames" position="0 0 0 0 0 0 1  1 0 0 0 0 0 1"
                    velocity="0 0 0 0 0 0  0 0 0 0 3 0"/>
  <UniformMass vertexMass="1"/>
  <FixedProjectiveConstraint name="fixed" indices="0"/>
</Node>)"));
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@frames.position"));
  EXPECT_EQ(std::vector<double>(x.begin(), x.begin() + 7),
            (std::vector<double>{0, 0, 0, 0, 0, 0, 1}));
  EXPECT_LT(x[8], -0.05);  // the other frame falls
  std::vector<std::size_t> rows;
  s.get<BaseProjectiveConstraint>("@fixed")->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
}

TEST(PartialFixedProjectiveConstraint, PointMovesAlongItsFreeDirectionOnly) {
  SceneHolder s;
  ASSERT_TRUE(
      s.load(std::string(R"(<Node name="root" gravity="1 -10 2" dt="0.01">)") + kSolver + R"(
  <MechanicalObject name="dofs" position="0 0 0  1 1 1"/>
  <UniformMass vertexMass="1"/>
  <PartialFixedProjectiveConstraint name="partial" indices="1" fixedDirections="1 0 1"/>
</Node>)"));
  const int n = 10;
  ASSERT_TRUE(s.step(n));
  const auto x = numbers(s.text("@dofs.position"));
  EXPECT_DOUBLE_EQ(x[3], 1);
  EXPECT_DOUBLE_EQ(x[5], 1);
  EXPECT_NEAR(x[4], 1 - 10 * 1e-4 * n * (n + 1) / 2, 1e-12);
  EXPECT_NEAR(x[0], 1e-4 * n * (n + 1) / 2, 1e-12);  // the free point falls along g
  std::vector<std::size_t> rows;
  s.get<BaseProjectiveConstraint>("@partial")->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{3, 5}));
}

TEST(PartialFixedProjectiveConstraint, RigidFrameKeepsItsCentreAndTurns) {
  SceneHolder s;
  ASSERT_TRUE(
      s.load(std::string(R"(<Node name="root" gravity="0 -10 0" dt="0.01">)") + kSolver + R"(
  <MechanicalObject template="Rigid3" name="frame" position="0 0 0 0 0 0 1" velocity="0 0 0 0 0 2"/>
  <UniformMass vertexMass="1"/>
  <PartialFixedProjectiveConstraint template="Rigid3" indices="0" fixedDirections="1 1 1 0 0 0"/>
</Node>)"));
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@frame.position"));
  EXPECT_EQ(std::vector<double>(x.begin(), x.begin() + 3), (std::vector<double>{0, 0, 0}));
  EXPECT_NEAR(2 * std::atan2(x[5], x[6]), 10 * 0.01 * 2, 1e-9);
}

TEST(PartialFixedProjectiveConstraint, BadInputIsReported) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<PartialFixedProjectiveConstraint indices="0" fixedDirections="1 0 1 1 1 1"/></Node>)",
                          {"expected 3 flags", "got 6"})
                .field,
            "fixedDirections");
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<FixedProjectiveConstraint template="Vec3" indices="0 3 9"/></Node>)",
                          {"2 indices out of range of the 1 points", "3 9"})
                .field,
            "indices");
}

}  // namespace
}  // namespace stroma::test
