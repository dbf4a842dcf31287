// SPDX-License-Identifier: MIT
// MeshSpringForceField: springs on the pairs of each element (stiffness per unit length, rest
// lengths from the rest positions), exact tangent and energy, rigid-motion invariance.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

TEST(MeshSpringForceField, OneSpringPerPairOfATetrahedron) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node gravity="0 0 0">
  <MeshTopology tetrahedra="0 1 2 3"/>
  <MechanicalObject name="dofs" position="0 0 0  2 0 0  0 1 0  0 0 1"/>
  <MeshSpringForceField name="springs" stiffness="100" damping="4"/>
</Node>)"));
  const auto springs = numbers(s.text("@springs.spring"));
  ASSERT_EQ(springs.size(), 6u * 5);
  // Spring 0-1: rest length 2, ks = 100 / 2, kd = 4 / 2.
  EXPECT_EQ(springs[0], 0);
  EXPECT_EQ(springs[1], 1);
  EXPECT_DOUBLE_EQ(springs[2], 50);
  EXPECT_DOUBLE_EQ(springs[3], 2);
  EXPECT_DOUBLE_EQ(springs[4], 2);
}

TEST(MeshSpringForceField, PassesTheForceFieldTest) {
  checkForceField(R"(<Node name="root" gravity="0 0 0">
  <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
  <MechanicalObject name="dofs" position="@grid.position"/>
  <MeshSpringForceField name="springs" stiffness="150"/>
</Node>)",
                  {.rotationInvariant = true});
}

TEST(MeshSpringForceField, DeformedMeshIsConsistent) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <MeshTopology tetrahedra="0 1 2 3  1 2 3 4"/>
  <MechanicalObject name="dofs" rest_position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1"
                    position="0.1 -0.1 0  1.3 0.1 0  0 0.8 0.2  0.1 0 1.2  0.9 1.2 1.1"/>
  <MeshSpringForceField name="springs" tetrahedraStiffness="200" linesStiffness="0"/>
</Node>)"));
  EXPECT_EQ(numbers(s.text("@springs.spring")).size(), 9u * 5);  // 6 + 6 - 3 shared
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::MatrixXd fd = check.finiteDifferenceStiffness();
  EXPECT_LT((check.matrixFreeStiffness() - fd).cwiseAbs().maxCoeff(), 1e-6 * scaleOf(fd));
  EXPECT_LT((check.assembled(0, 0, 1) - fd).cwiseAbs().maxCoeff(), 1e-6 * scaleOf(fd));
  const Eigen::VectorXd f = check.force();
  EXPECT_LT((f - check.finiteDifferenceForce()).cwiseAbs().maxCoeff(), 1e-6 * scaleOf(f));
}

TEST(MeshSpringForceField, RigidMotionOfTheRestShapeGivesNoForce) {
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.1, Vec3d(-1, 2, 0.5).normalized()).toRotationMatrix();
  std::string moved;
  for (const Vec3d& p : {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 1, 0), Vec3d(0, 1, 0),
                         Vec3d(0, 0, 1), Vec3d(1, 0, 1), Vec3d(1, 1, 1), Vec3d(0, 1, 1)}) {
    const Vec3d q = R * p + Vec3d(5, -2, 1);
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g  ", q.x(), q.y(), q.z());
    moved += buffer;
  }
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <MeshTopology hexahedra="0 1 2 3 4 5 6 7"/>
  <MechanicalObject name="dofs" rest_position="0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1"
                    position=")" +
                     moved + R"("/>
  <MeshSpringForceField name="springs" cubesStiffness="1000"/>
</Node>)"));
  EXPECT_EQ(numbers(s.text("@springs.spring")).size(), 28u * 5);
  ForceFieldChecker check(s.scene(), s.root());
  EXPECT_LT(check.force().cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT(check.energy(), 1e-20);
}

TEST(MeshSpringForceField, SharedPairsGetOneSpring) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node gravity="0 0 0">
  <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
  <MechanicalObject name="dofs" position="@grid.position"/>
  <MeshSpringForceField name="springs" cubesStiffness="10"/>
</Node>)"));
  EXPECT_EQ(numbers(s.text("@springs.spring")).size(), (2u * 28 - 6) * 5);
}

TEST(MeshSpringForceField, MissingTopologyIsAnError) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<MeshSpringForceField stiffness="1"/></Node>)",
                          {"needs a topology"})
                .field,
            "topology");
}

}  // namespace
}  // namespace stroma::test
