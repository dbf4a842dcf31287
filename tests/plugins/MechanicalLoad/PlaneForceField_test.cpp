// SPDX-License-Identifier: MIT
// PlaneForceField: a point falling on the floor rests at the depth m g / k; its stiffness and
// energy are consistent with its forces; the plane of a non-unit normal; rigid frames.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

std::string fallingScene(const std::string& templateName, const std::string& position,
                         const std::string& plane) {
  return R"(
<Node name="root" gravity="0 -9.81 0" dt="0.005">
  <EulerImplicitSolver rayleighMass="0.2" rayleighStiffness="0.05"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>
  <MechanicalObject template=")" +
         templateName + R"(" name="dofs" position=")" + position + R"("/>
  <UniformMass vertexMass="2"/>
  <PlaneForceField name="floor" )" +
         plane + R"(/>
</Node>)";
}

TEST(PlaneForceField, FallingPointRestsAtTheDepthMgOverK) {
  SceneHolder s;
  ASSERT_TRUE(s.load(fallingScene("Vec3", "0.3 0.5 -0.2  1 0.2 0",
                                  R"(normal="0 1 0" d="0" stiffness="1000" damping="20")")));
  double lowest = 1;
  for (int i = 0; i < 1200; ++i) {
    ASSERT_TRUE(s.step());
    lowest = std::min(lowest, numbers(s.text("@dofs.position"))[1]);
  }
  const auto x = numbers(s.text("@dofs.position"));
  const double depth = 2 * 9.81 / 1000;
  EXPECT_NEAR(x[1], -depth, 1e-7);
  EXPECT_NEAR(x[4], -depth, 1e-7);
  EXPECT_NEAR(x[0], 0.3, 1e-12);  // no tangential force at rest
  EXPECT_GT(lowest, -5 * depth);  // it never went through the floor
}

TEST(PlaneForceField, NonUnitNormalKeepsThePlane) {
  // normal 0 2 0 and d = 2: the plane y = 1, pushing with stiffness k along the unit normal.
  SceneHolder s;
  ASSERT_TRUE(s.load(
      fallingScene("Vec3", "0 3 0", R"(normal="0 2 0" d="2" stiffness="500" damping="10")")));
  ASSERT_TRUE(s.step(1500));
  EXPECT_NEAR(numbers(s.text("@dofs.position"))[1], 1 - 2 * 9.81 / 500, 1e-7);
}

TEST(PlaneForceField, RigidFrameCentreRestsOnTheFloor) {
  SceneHolder s;
  ASSERT_TRUE(s.load(fallingScene("Rigid3", "0 0.4 0 0 0 0 1",
                                  R"(normal="0 1 0" d="-1" stiffness="2000" damping="20")")));
  ASSERT_TRUE(s.step(1200));
  EXPECT_NEAR(numbers(s.text("@dofs.position"))[1], -1 - 2 * 9.81 / 2000, 1e-7);
}

// The generic force-field test, with every point a spacing below the plane so that the random
// perturbation keeps them in contact (the force has a kink at the plane).
TEST(PlaneForceField, PassesTheForceFieldTest) {
  checkForceField(R"(<Node name="root" gravity="0 0 0">
  <MechanicalObject name="dofs" position="0 -1 0  1 -1.2 0  0 -1.1 1  1 -1 1"/>
  <PlaneForceField name="plane" normal="0.1 1 -0.2" d="0" stiffness="800" damping="3"/>
</Node>)",
                  {.zeroAtRest = false});
}

TEST(PlaneForceField, StiffnessAndEnergyAreConsistentWithTheForce) {
  // Points below the slanted plane (two), above it (one); no velocity.
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node gravity="0 0 0">
  <MechanicalObject position="0 -0.5 0  0.3 -0.2 0.1  0 2 0"/>
  <PlaneForceField normal="0.2 1 0.1" d="0.1" stiffness="300" damping="7"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::MatrixXd fd = check.finiteDifferenceStiffness();
  EXPECT_LT((check.matrixFreeStiffness() - fd).cwiseAbs().maxCoeff(), 1e-6 * scaleOf(fd));
  EXPECT_LT((check.assembled(0, 0, 1) - fd).cwiseAbs().maxCoeff(), 1e-6 * scaleOf(fd));
  EXPECT_EQ(fd.bottomRightCorner(3, 3).cwiseAbs().maxCoeff(), 0);  // the point above: nothing
  const Eigen::VectorXd f = check.force();
  EXPECT_LT((f - check.finiteDifferenceForce()).cwiseAbs().maxCoeff(), 1e-6 * scaleOf(f));
  // Force k * depth along the unit normal.
  const Vec3d n = Vec3d(0.2, 1, 0.1).normalized();
  const double depth = 0.1 / Vec3d(0.2, 1, 0.1).norm() - Vec3d(0, -0.5, 0).dot(n);
  EXPECT_LT((f.head<3>() - 300 * depth * n).norm(), 1e-12);
}

TEST(PlaneForceField, DampingScalesWithTheDepth) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node gravity="0 0 0">
  <MechanicalObject position="0 -0.1 0" velocity="1 -2 0"/>
  <PlaneForceField stiffness="100" damping="50"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  // -k delta n + c delta v with delta = -0.1.
  EXPECT_NEAR(f[0], 50 * -0.1 * 1, 1e-12);
  EXPECT_NEAR(f[1], 100 * 0.1 + 50 * -0.1 * -2, 1e-12);
  // B = df/dv = c delta I.
  const Eigen::MatrixXd B = check.matrixFreeStiffness(1) - check.matrixFreeStiffness(0);
  EXPECT_TRUE(B.isApprox(-5 * Eigen::MatrixXd::Identity(3, 3)));
}

TEST(PlaneForceField, ZeroNormalIsAnError) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<PlaneForceField normal="0 0 0"/></Node>)",
                          {"the normal is zero"})
                .field,
            "normal");
}

}  // namespace
}  // namespace stroma::test
