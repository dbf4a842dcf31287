// SPDX-License-Identifier: MIT
// URDFLoader: the subgraph of the 2-link arm (joint state, link frames, joint names); a joint
// held against its limit by gravity stays on it; a floating base falls freely; a .urdf file is
// a scene by itself; bad input (a file urdfdom cannot parse, a joint whose parent link is
// missing, a negative mass, an inertia that is not positive definite) is an error naming the
// component, its field and the file.
#include "plugins/URDF/URDFTestRobots.h"

namespace stroma::test {
namespace {

std::vector<double> valuesAt(const Scene& scene, const std::string& path) {
  return positionsAt(scene, path);
}

TEST(URDFLoader, BuildsTheArmsJointsAndLinks) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder,
                      armScene(folder, twoLinkArm(),
                               "<EulerImplicitSolver/><SparseLDLSolver/>")))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  EXPECT_EQ(valuesAt(scene, "/root/arm/joints").size(), 2u);
  EXPECT_EQ(valuesAt(scene, "/root/arm/links/frames").size(), 3u * 7u);
  std::string why;
  const Base* loader = resolveObjectPath(scene.root(), "@/root/loader", why);
  ASSERT_NE(loader, nullptr) << why;
  const auto* names =
      dynamic_cast<const Data<std::vector<std::string>>*>(loader->findData("jointNames"));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->value(), (std::vector<std::string>{"joint1", "joint2"}));
  // Gravity swings the arm down: joint 1 turns toward -z (positive about y).
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene.step()) << problems(scene.log());
  EXPECT_GT(valuesAt(scene, "/root/arm/joints")[0], 0.01);
}

TEST(URDFLoader, JointHeldAtItsLimitStaysOnIt) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ArmOptions arm;
  arm.secondLink = false;  // a second link swinging below would pull the first off its stop
  arm.joint1Type = "revolute";
  arm.joint1Extra = R"(<limit lower="-0.2" upper="0.2" effort="10" velocity="1"/>)";
  ASSERT_TRUE(loadArm(scene, folder,
                      armScene(folder, twoLinkArm(arm),
                               "<EulerImplicitSolver/><SparseLDLSolver/>")))
      << problems(scene.log());
  double reached = -1;
  for (int i = 0; i < 1000; ++i) {
    ASSERT_TRUE(scene.step()) << problems(scene.log());
    const double q1 = valuesAt(scene, "/root/arm/joints")[0];
    EXPECT_LE(q1, 0.2 + 1e-12) << "step " << i;
    if (q1 >= 0.2 - 1e-12 && reached < 0) reached = i * 1e-3;
  }
  // Gravity pulls the link down (positive q1): it reaches the upper limit and stays there.
  EXPECT_GT(reached, 0.0);
  EXPECT_NEAR(valuesAt(scene, "/root/arm/joints")[0], 0.2, 1e-12);
}

TEST(URDFLoader, ImposedJointMotionFollowsItsKeysAndDrivesTheRest) {
  // Joint 1 turned from 0 to 0.5 rad between t = 0 and 1 s by LinearMovementConstraint on the
  // joint values (Vec1d), joint 2 free: joint 1 is exactly on its ramp at every step, joint 2
  // swings (gravity and the first link's motion).
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder,
                      armScene(folder, twoLinkArm(), "<EulerImplicitSolver/><SparseLDLSolver/>",
                               "<LinearMovementConstraint template=\"Vec1d\" "
                               "mstate=\"@arm/joints\" indices=\"0\" keyTimes=\"0 1 10\" "
                               "movements=\"0  0.5  0.5\"/>")))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  for (int i = 1; i <= 500; ++i) {
    ASSERT_TRUE(scene.step()) << problems(scene.log());
    ASSERT_NEAR(valuesAt(scene, "/root/arm/joints")[0], 0.5 * i * 1e-3, 1e-12) << "step " << i;
  }
  EXPECT_GT(std::abs(valuesAt(scene, "/root/arm/joints")[1]), 0.01);
}

TEST(URDFLoader, PlanarJointSlidesInItsPlaneAndTurnsAboutItsNormal) {
  // A 1 kg puck on a planar joint of normal z, gravity (-3, 0, -9.81): it falls along -x only
  // (z is out of its plane), x = -3 t^2 / 2, and nothing turns it.
  const std::string urdf = R"(<?xml version="1.0"?>
<robot name="puck">
  <link name="table"/>
  <link name="puck"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="slide" type="planar"><parent link="table"/><child link="puck"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/></joint>
</robot>
)";
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder,
                      armScene(folder, urdf, "<NewmarkImplicitSolver/><SparseLDLSolver/>", "",
                               "-3 0 -9.81")))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  std::string why;
  const auto* names = dynamic_cast<const Data<std::vector<std::string>>*>(
      resolveObjectPath(scene.root(), "@/root/loader", why)->findData("jointNames"));
  EXPECT_EQ(names->value(), (std::vector<std::string>{"slide_u", "slide_v", "slide_theta"}));
  for (int i = 0; i < 500; ++i) ASSERT_TRUE(scene.step()) << problems(scene.log());
  // Frames: table, the two slides' virtual links, puck.
  const std::vector<double> frames = valuesAt(scene, "/root/puck/links/frames");
  ASSERT_EQ(frames.size(), 4u * 7u);
  const double* puck = &frames[3 * 7];
  EXPECT_NEAR(puck[0], -0.5 * 3 * 0.25, 1e-9);  // t = 0.5 s
  EXPECT_NEAR(puck[1], 0.0, 1e-12);
  EXPECT_NEAR(puck[2], 0.1, 1e-12);
  EXPECT_NEAR(std::abs(puck[6]), 1.0, 1e-12);  // qw: not turned
}

TEST(URDFLoader, FloatingBaseFallsFreely) {
  RobotFolder folder;
  ArmOptions floating;
  floating.baseMass = 2;  // a massless base would make its rotation and joint 1's the same
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder,
                      armScene(folder, twoLinkArm(floating),
                               "<NewmarkImplicitSolver/><SparseLDLSolver/>", "", "0 0 -9.81",
                               "fixedBase=\"false\"")))
      << problems(scene.log());
  ASSERT_EQ(valuesAt(scene, "/root/arm/joints").size(), 8u);  // x y z yaw pitch roll, 2 joints
  for (int i = 0; i < 500; ++i) ASSERT_TRUE(scene.step()) << problems(scene.log());
  // In uniform gravity nothing turns: the base drops by g t^2 / 2.
  const std::vector<double> q = valuesAt(scene, "/root/arm/joints");
  EXPECT_NEAR(q[2], -0.5 * 9.81 * 0.25, 1e-6);
  for (int j : {0, 1, 3, 4, 5, 6, 7}) EXPECT_NEAR(q[j], 0.0, 1e-9) << "value " << j;
}

TEST(URDFLoader, AUrdfFileIsASceneByItself) {
  RobotFolder folder;
  const auto file = folder.write("arm.urdf", twoLinkArm());
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadFile(file)) << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  EXPECT_TRUE(scene.root().gravity().isApprox(Vec3d(0, 0, -9.81)));
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene.step()) << problems(scene.log());
  EXPECT_GT(valuesAt(scene, "/root/arm/joints")[0], 0.01);  // it swings down
}

// The one error of a scene whose URDF is `urdf`.
Message loadError(const std::string& urdf) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(loadArm(scene, folder, armScene(folder, urdf, "")));
  for (const Message& m : scene.log().messages())
    if (m.level == MessageLevel::error) return m;
  ADD_FAILURE() << "no error";
  return {};
}

TEST(URDFLoader, BadRobotsAreErrorsNamingComponentFieldAndFile) {
  {
    const Message m = loadError("<robot name=\"r\"><link name=\"a\"></robot>");
    EXPECT_EQ(m.componentClass, "URDFLoader");
    EXPECT_EQ(m.field, "filename");
    EXPECT_NE(m.text.find("robot.urdf"), std::string::npos) << m.text;
    EXPECT_NE(m.text.find("not a valid URDF"), std::string::npos) << m.text;
    EXPECT_NE(m.text.find("(line 1: "), std::string::npos) << m.text;
    std::printf("unparsable: %s\n", m.text.c_str());
  }
  {
    std::string urdf = twoLinkArm();
    urdf.replace(urdf.find("<parent link=\"link1\"/>"), 22, "<parent link=\"nowhere\"/>");
    const Message m = loadError(urdf);
    EXPECT_EQ(m.componentClass, "URDFLoader");
    EXPECT_EQ(m.field, "filename");
    EXPECT_NE(m.text.find("nowhere"), std::string::npos) << m.text;
    std::printf("missing parent: %s\n", m.text.c_str());
  }
  {
    ArmOptions arm;
    arm.mass = -2;
    const Message m = loadError(twoLinkArm(arm));
    EXPECT_EQ(m.componentClass, "URDFLoader");
    EXPECT_NE(m.text.find("link 'link1'"), std::string::npos) << m.text;
    EXPECT_NE(m.text.find("mass"), std::string::npos) << m.text;
    std::printf("negative mass: %s\n", m.text.c_str());
  }
  {
    std::string urdf = twoLinkArm();
    const auto at = urdf.find("ixx=\"1e-9\"");
    urdf.replace(at, 10, "ixx=\"-1\"");
    const Message m = loadError(urdf);
    EXPECT_EQ(m.componentClass, "URDFLoader");
    EXPECT_NE(m.text.find("not positive definite"), std::string::npos) << m.text;
    std::printf("bad inertia: %s\n", m.text.c_str());
  }
}

}  // namespace
}  // namespace stroma::test
