// SPDX-License-Identifier: MIT
// URDFLoader collisionModels: a link's <collision> sphere, mesh, box and cylinder become
// collision models on points mapped to the link; the one-link pendulum swinging down under gravity is stopped by a
// fixed sphere in its path (the contact force reaches the joint through the mappings), while
// the mesh's points follow the link's frame.
#include "plugins/URDF/URDFTestRobots.h"

namespace stroma::test {
namespace {

// One link of 0.5 m about y (horizontal at q = 0, hanging at q = pi/2), a collision sphere of
// 3 cm at its tip and a collision mesh (a triangle) near its middle.
const char* kPendulum = R"(<?xml version="1.0"?>
<robot name="pendulum">
  <link name="base_link"/>
  <link name="link1">
    <inertial><origin xyz="0.25 0 0"/><mass value="1"/>
      <inertia ixx="1e-4" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.02"/></inertial>
    <collision><origin xyz="0.5 0 0"/><geometry><sphere radius="0.03"/></geometry></collision>
    <collision><origin xyz="0.2 0 0"/><geometry><mesh filename="triangle.obj"/></geometry></collision>
  </link>
  <joint name="joint1" type="continuous"><parent link="base_link"/><child link="link1"/>
    <axis xyz="0 1 0"/></joint>
</robot>
)";

// `tip`: the <geometry> of the collision at the link's tip (default the 3 cm sphere).
double swing(bool obstacle, const std::string& tip = "") {
  RobotFolder folder;
  folder.write("triangle.obj", "v 0 0 0\nv 0.05 0 0\nv 0 0.05 0\nf 1 2 3\n");
  // The obstacle: 3 cm sphere where the tip passes at q = 0.8 rad.
  const double q = 0.8, L = 0.5;
  const std::string center =
      std::to_string(L * std::cos(q)) + " 0 " + std::to_string(-L * std::sin(q));
  const std::string pipeline = R"(<CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
      <MinProximityIntersection alarmDistance="0.02" contactDistance="0.005"/>
      <CollisionResponse/>
      <Node name="Arm"><EulerImplicitSolver/><SparseLDLSolver/>
        <URDFLoader filename="robot.urdf" collisionModels="true" contactStiffness="1000"/>
      </Node>)";
  const std::string obstacleNode =
      obstacle ? "<Node name=\"Obstacle\"><MechanicalObject template=\"Vec3d\" position=\"" +
                     center +
                     "\"/><SphereCollisionModel radius=\"0.03\" moving=\"false\" "
                     "simulated=\"false\"/></Node>"
               : "";
  std::string urdf = kPendulum;
  if (!tip.empty()) {
    const std::string sphere = "<sphere radius=\"0.03\"/>";
    urdf.replace(urdf.find(sphere), sphere.size(), tip);
  }
  folder.write("robot.urdf", urdf);
  const std::string xml = "<Node name=\"root\" gravity=\"0 0 -9.81\" dt=\"0.001\">" + pipeline +
                          obstacleNode + "</Node>";
  Runtime runtime;
  Scene scene(runtime);
  if (!loadArm(scene, folder, xml)) {
    ADD_FAILURE() << problems(scene.log());
    return 0;
  }
  EXPECT_EQ(problems(scene.log()), "");
  double largest = 0;
  for (int i = 0; i < 600; ++i) {
    if (!scene.step()) {
      ADD_FAILURE() << problems(scene.log());
      return 0;
    }
    const double q1 = positionsAt(scene, "/root/Arm/pendulum/joints")[0];
    largest = std::max(largest, q1);
    // The mesh's first point, at (0.2, 0, 0) in the link, follows the link's frame.
    const std::vector<double> p =
        positionsAt(scene, "/root/Arm/pendulum/links/collision_link1_1/points");
    if (p.size() >= 3) {
      EXPECT_NEAR(p[0], 0.2 * std::cos(q1), 1e-9);
      EXPECT_NEAR(p[2], -0.2 * std::sin(q1), 1e-9);
    } else {
      ADD_FAILURE() << "no collision mesh points";
      return 0;
    }
  }
  return largest;
}

TEST(URDFCollision, ObstacleStopsTheSwingingLink) {
  const double free = swing(false), stopped = swing(true);
  std::printf("largest joint angle over 0.6 s: %.3f rad free, %.3f rad with the obstacle at 0.8 "
              "rad (touching from about %.3f)\n",
              free, stopped, 0.8 - 0.06 / 0.5);
  EXPECT_GT(free, 1.2);                // it swings through the obstacle's place without it
  EXPECT_LT(stopped, 0.8 - 0.03 / 0.5);  // the two spheres overlap by less than a radius
  EXPECT_GT(stopped, 0.5);
}

TEST(URDFCollision, ObstacleStopsALinkCollidedAsABoxOrACylinder) {
  // The tip as a 6 cm cube, then as a cylinder of radius 3 cm and length 6 cm (its axis along
  // the link's z, in the plane of the swing): their triangles, edges and points meet the sphere.
  for (const std::string& tip : {std::string("<box size=\"0.06 0.06 0.06\"/>"),
                                std::string("<cylinder radius=\"0.03\" length=\"0.06\"/>")}) {
    SCOPED_TRACE(tip);
    const double free = swing(false, tip), stopped = swing(true, tip);
    std::printf("%s: largest joint angle %.3f rad free, %.3f rad with the obstacle at 0.8 rad\n",
                tip.c_str(), free, stopped);
    EXPECT_GT(free, 1.2);
    EXPECT_LT(stopped, 0.8 - 0.03 / 0.5);
    EXPECT_GT(stopped, 0.5);
  }
}

}  // namespace
}  // namespace stroma::test
