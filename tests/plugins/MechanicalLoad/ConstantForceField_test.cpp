// SPDX-License-Identifier: MIT
// ConstantForceField on rigid frames: force and torque give the accelerations F / m and
// I^-1 T of the exact backward Euler solution; forces on points in a plane and on a line.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"

namespace stroma::test {
namespace {

TEST(ConstantForceField, ForceAndTorqueOnARigidFrame) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0" dt="0.01">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>
  <MechanicalObject template="Rigid3" name="frame" position="0 0 0 0 0 0 1"/>
  <UniformMass vertexMass="2 1 [1 0 0,0 1 0,0 0 4]"/>
  <ConstantForceField template="Rigid3" indices="0" forces="4 0 0  0 0 2"/>
</Node>)"));
  ASSERT_TRUE(s.step(10));
  const auto v = numbers(s.text("@frame.velocity"));
  EXPECT_NEAR(v[0], 10 * 0.01 * 4 / 2, 1e-12);        // F / m
  EXPECT_NEAR(v[5], 10 * 0.01 * 2 / (2 * 4), 1e-12);  // T / (m J_zz)
  EXPECT_NEAR(v[1] + v[2] + v[3] + v[4], 0, 1e-14);
}

TEST(ConstantForceField, TotalForceIsSpread) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node gravity="0 0 0"><MechanicalObject position="0 0 0 1 0 0"/>
<ConstantForceField totalForce="0 4 0" force="1 0 0"/></Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  EXPECT_TRUE(f.isApprox((Eigen::VectorXd(6) << 1, 2, 0, 1, 2, 0).finished()));
  EXPECT_LT((check.finiteDifferenceForce() - f).norm(), 1e-6);
}

TEST(ConstantForceField, ForcesInAPlaneAndOnALine) {
  // A force has as many components as a point: 2 in a plane (Vec2d), 1 on a line (Vec1d).
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <Node name="plane">
    <MechanicalObject template="Vec2" name="dofs" position="0 0  1 2  3 1"/>
    <ConstantForceField indices="1 2" forces="1 -2  0.5 4"/>
  </Node>
  <Node name="line">
    <MechanicalObject template="Vec1" name="dofs" position="0 2"/>
    <ConstantForceField totalForce="6" force="1"/>
  </Node>
</Node>)"));
  MechanicalOperations mop(s.root(), s.scene().timing());
  mop.computeForce(MechanicalParams{}, VecId::force());
  EXPECT_EQ(s.text("@plane/dofs.force"), "0 0 1 -2 0.5 4");
  EXPECT_EQ(s.text("@line/dofs.force"), "4 4");
  // E = -sum f.x: plane -(1 - 4) - (1.5 + 4), line -(0 + 8).
  EXPECT_DOUBLE_EQ(mop.potentialEnergy(MechanicalParams{}), 3 - 5.5 - 8);
}

}  // namespace
}  // namespace stroma::test
