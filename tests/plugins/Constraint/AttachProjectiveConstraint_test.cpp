// SPDX-License-Identifier: MIT
// AttachProjectiveConstraint (one way): the follower ends every step where its leader is, with
// its velocity; the leader does not feel the follower (it falls freely, closed form) though a
// spring pulls the follower; projected CG and fixed-row LDL agree; a released pair (factor 0)
// is free; bad input is reported.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"

namespace stroma::test {
namespace {

const char* kMatrixFree = R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="200" tolerance="1e-14" threshold="0"/>)";
const char* kAssembled = R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <SparseLDLSolver/>)";

// Leader A: one free point thrown sideways. Follower B: point 0 attached to A's point 0, point
// 1 hanging from it by a spring.
std::string scene(const std::string& solver, const std::string& attach) {
  return R"(<Node name="root" gravity="1 -10 0" dt="0.01">)" + solver + R"(
  <Node name="A">
    <MechanicalObject name="dofs" position="0 0 0" velocity="3 0 0"/>
    <UniformMass vertexMass="1"/>
  </Node>
  <Node name="B">
    <MechanicalObject name="dofs" position="0 0 0  0 -1 0"/>
    <UniformMass vertexMass="1"/>
    <SpringForceField spring="0 1 500 0 1"/>
  </Node>
  )" + attach +
         "\n</Node>";
}

Vec3d point(const std::vector<double>& x, int i) { return {x[3 * i], x[3 * i + 1], x[3 * i + 2]}; }

TEST(AttachProjectiveConstraint, FollowerEndsEachStepOnItsLeaderOneWay) {
  std::vector<std::vector<double>> followers;
  for (const char* solver : {kMatrixFree, kAssembled}) {
    SceneHolder s;
    ASSERT_TRUE(s.load(scene(solver, R"(<AttachProjectiveConstraint object1="@A" object2="@B"
        indices1="0" indices2="0"/>)")));
    const int n = 20;
    ASSERT_TRUE(s.step(n));
    const auto a = numbers(s.text("@A/dofs.position"));
    const auto b = numbers(s.text("@B/dofs.position"));
    // The leader flies freely: backward Euler, n h v0 + h^2 n (n + 1) / 2 g.
    const Vec3d fallen = 0.01 * n * Vec3d(3, 0, 0) + 1e-4 * n * (n + 1) / 2.0 * Vec3d(1, -10, 0);
    EXPECT_LT((point(a, 0) - fallen).norm(), 1e-12);
    EXPECT_EQ(point(b, 0), point(a, 0));
    EXPECT_EQ(point(numbers(s.text("@B/dofs.velocity")), 0),
              point(numbers(s.text("@A/dofs.velocity")), 0));
    EXPECT_LT(b[3], b[0] - 0.05);  // the hanging point swings behind
    followers.push_back(b);
  }
  for (std::size_t k = 0; k < followers[0].size(); ++k)
    EXPECT_NEAR(followers[0][k], followers[1][k], 1e-10) << k;
}

TEST(AttachProjectiveConstraint, ReleasedPairIsFree) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kMatrixFree, R"(<AttachProjectiveConstraint object1="@A/dofs"
      object2="@B/dofs" indices1="0" indices2="0" constraintFactor="0"/>)")));
  ASSERT_TRUE(s.step(5));
  // Both points of B fall together (the spring stays at rest length), A flies away.
  const auto b = numbers(s.text("@B/dofs.position"));
  const Vec3d fallen = 1e-4 * 15 * Vec3d(1, -10, 0);
  EXPECT_LT((point(b, 0) - fallen).norm(), 1e-12);
  EXPECT_LT((point(b, 1) - fallen - Vec3d(0, -1, 0)).norm(), 1e-12);
  EXPECT_NEAR(numbers(s.text("@A/dofs.position"))[0], 0.15 + 15e-4, 1e-12);
}

TEST(AttachProjectiveConstraint, BadInputIsReported) {
  const char* solver = "<EulerImplicitSolver/><CGLinearSolver/>";
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(scene(solver, R"(<AttachProjectiveConstraint object1="@A"
      object2="@B" indices1="0" indices2="0 1"/>)"),
                          {"has 2 indices for the 1 of indices1"})
                .field,
            "indices2");
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(scene(solver, R"(<AttachProjectiveConstraint object1="@A"
      object2="@B" indices1="3" indices2="0"/>)"),
                          {"1 index out of range of the 1 points", "3"})
                .field,
            "indices1");
  SceneHolder u;
  EXPECT_EQ(u.loadFailing(scene(solver, R"(<AttachProjectiveConstraint object1="@A"
      object2="@B" indices1="0" indices2="0" twoWay="1"/>)"),
                          {"two-way attachment"})
                .field,
            "twoWay");
  SceneHolder w;
  EXPECT_EQ(w.loadFailing(scene(solver, R"(<AttachProjectiveConstraint object1="@A"
      object2="@B" indices1="0" indices2="0" constraintFactor="0.5"/>)"),
                          {"is not provided: give 1 (attached) or 0"})
                .field,
            "constraintFactor");
}

}  // namespace
}  // namespace stroma::test
