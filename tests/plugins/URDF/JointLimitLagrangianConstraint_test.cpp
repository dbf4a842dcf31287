// SPDX-License-Identifier: MIT
// Joint limits as Lagrange multipliers (JointLimitLagrangianConstraint, chosen by URDFLoader
// under FreeMotionAnimationLoop): a link pulled by gravity against its stop stays on it within
// the constraint solver's tolerance, and the stop's torque is the one that balances gravity's;
// the limit lets the link go when it swings back; bad bounds are errors naming the field.
#include "plugins/TestPlugin/TestSupport.h"
#include "plugins/URDF/URDFTestRobots.h"

namespace stroma::test {
namespace {

constexpr const char* kLagrangianSolvers =
    "<FreeMotionAnimationLoop/>\n"
    "<GenericConstraintSolver tolerance=\"1e-12\" maxIterations=\"200\"/>\n"
    "<EulerImplicitSolver rayleighStiffness=\"0\" rayleighMass=\"0\"/>\n"
    "<SparseLDLSolver/>\n"
    "<LinearSolverConstraintCorrection/>";

const Base* objectAt(const Scene& scene, const std::string& path) {
  std::string why;
  const Base* object = resolveObjectPath(scene.root(), "@" + path, why);
  EXPECT_NE(object, nullptr) << why;
  return object;
}

std::vector<double> doublesAt(const Scene& scene, const std::string& path,
                              const std::string& field) {
  const Base* object = objectAt(scene, path);
  if (!object) return {};
  const auto* data = dynamic_cast<const Data<std::vector<double>>*>(object->findData(field));
  EXPECT_NE(data, nullptr) << path << "." << field;
  return data ? data->value() : std::vector<double>{};
}

// One link of 1 kg, its center 0.25 m from joint 1 (about y), limited to [-0.2, 0.2]: gravity
// (-z) turns it toward positive q, onto the upper stop.
std::string limitedLink() {
  ArmOptions arm;
  arm.secondLink = false;
  arm.joint1Type = "revolute";
  arm.joint1Extra = R"(<limit lower="-0.2" upper="0.2" effort="10" velocity="1"/>)";
  return twoLinkArm(arm);
}

TEST(JointLimitLagrangianConstraint, LinkRestsOnItsStopWithGravitysTorque) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder, armScene(folder, limitedLink(), kLagrangianSolvers)))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  const Base* limits = objectAt(scene, "/root/arm/limits");
  ASSERT_NE(limits, nullptr);
  EXPECT_EQ(limits->className(), "JointLimitLagrangianConstraint");  // auto: a constraint solver
  double worst = -1;
  int reached = -1;
  for (int i = 0; i < 1000; ++i) {
    ASSERT_TRUE(scene.step()) << problems(scene.log());
    const double q1 = positionsAt(scene, "/root/arm/joints")[0];
    worst = std::max(worst, q1 - 0.2);
    if (q1 >= 0.2 - 1e-9 && reached < 0) reached = i;
  }
  // It reaches the stop (free fall of a rod: about 0.2 s) and never passes it by more than the
  // constraint solver's tolerance.
  EXPECT_GT(reached, 50);
  EXPECT_LT(reached, 500);
  EXPECT_LE(worst, 1e-10);
  const double q1 = positionsAt(scene, "/root/arm/joints")[0];
  EXPECT_NEAR(q1, 0.2, 1e-10);
  // At rest on the stop, its torque balances gravity's, m g (L/2) cos q1 about +y pushing q up:
  // the stop pushes down (negative).
  const double gravityTorque = 1.0 * 9.81 * 0.25 * std::cos(0.2);
  const std::vector<double> forces = doublesAt(scene, "/root/arm/limits", "forces");
  ASSERT_EQ(forces.size(), 1u);
  EXPECT_NEAR(forces[0], -gravityTorque, 1e-6 * gravityTorque);
  std::printf("reached the stop at step %d; largest q1 - upper %.3g; at rest q1 - upper = %.3g, "
              "stop torque %.9f N m (gravity's %.9f)\n",
              reached, worst, q1 - 0.2, forces[0], gravityTorque);
}

TEST(JointLimitLagrangianConstraint, StopLetsTheLinkGoWhenPulledInward) {
  // Gravity along +z: the link, at rest on its upper stop, swings the other way, freely.
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder,
                      armScene(folder, limitedLink(), kLagrangianSolvers, "", "0 0 9.81",
                               "initialJoints=\"0.2\"")))
      << problems(scene.log());
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene.step()) << problems(scene.log());
  // 0.1 s after release: a point mass 0.25 m from the axis starts at g cos(0.2) / 0.25 = 38
  // rad/s^2, about 0.19 rad in 0.1 s; the stop held nothing back.
  EXPECT_LT(positionsAt(scene, "/root/arm/joints")[0], 0.2 - 0.1);
  EXPECT_EQ(doublesAt(scene, "/root/arm/limits", "forces")[0], 0.0);
}

TEST(JointLimitLagrangianConstraint, ChosenByTheLoaderAndBadBoundsAreErrors) {
  {
    RobotFolder folder;
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadArm(scene, folder,
                        armScene(folder, limitedLink(), "<EulerImplicitSolver/><SparseLDLSolver/>",
                                 "", "0 0 -9.81", "jointLimits=\"auto\"")));
    EXPECT_EQ(objectAt(scene, "/root/arm/limits")->className(), "JointLimitConstraint");
  }
  {
    RobotFolder folder;
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadArm(scene, folder,
                        armScene(folder, limitedLink(), kLagrangianSolvers, "", "0 0 -9.81",
                                 "jointLimits=\"none\"")));
    std::string why;
    EXPECT_EQ(resolveObjectPath(scene.root(), "@/root/arm/limits", why), nullptr);
  }
  {
    RobotFolder folder;
    Runtime runtime;
    Scene scene(runtime);
    EXPECT_FALSE(loadArm(
        scene, folder,
        armScene(folder, limitedLink(), kLagrangianSolvers,
                 "<JointLimitLagrangianConstraint name=\"extra\" mstate=\"@arm/joints\" "
                 "indices=\"0\" lower=\"0.3\" upper=\"0.1\"/>")));
    EXPECT_TRUE(hasError(scene.log(), "/root/extra", "lower", "empty"))
        << problems(scene.log());
  }
}

}  // namespace
}  // namespace stroma::test
