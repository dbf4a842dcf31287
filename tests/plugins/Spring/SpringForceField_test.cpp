// SPDX-License-Identifier: MIT
// SpringForceField: forces = -grad(energy), exact tangent stiffness (matrix-free and assembled)
// against central finite differences, zero force under rigid motion, interaction springs
// between two states, a hanging mass at its analytic equilibrium, and bad spring lists.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

// Four points, springs stretched, compressed, at rest, and of zero rest length (an attachment).
const char* kFourPoints = R"(
<Node name="root" gravity="0 0 0">
  <MechanicalObject name="dofs" position="0 0 0  1.3 0.1 -0.2  0.2 0.9 0.1  0.4 0.3 1.1"/>
  <SpringForceField name="springs"
      spring="0 1 100 0 1.0   1 2 250 0 2.0   2 3 80 0 1.0   0 3 40 0 0   0 2 60 0 0.9219544457"/>
</Node>)";

// The project's generic force-field test: every pair of a cube's corners joined, at rest.
TEST(SpringForceField, PassesTheForceFieldTest) {
  std::string springs;
  const std::vector<Vec3d> corners{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0},
                                   {0, 0, 2}, {2, 0, 2}, {0, 2, 2}, {2, 2, 2}};
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j) {
      char spring[96];
      std::snprintf(spring, sizeof spring, "%d %d %d 0 %.17g  ", i, j, 100 + 10 * i,
                    (corners[i] - corners[j]).norm());
      springs += spring;
    }
  const auto report = checkForceField(R"(<Node name="root" gravity="0 0 0">
  <MechanicalObject name="dofs" position="0 0 0  2 0 0  0 2 0  2 2 0  0 0 2  2 0 2  0 2 2  2 2 2"/>
  <SpringForceField name="springs" spring=")" +
                                          springs + R"("/>
</Node>)",
                                      {.rotationInvariant = true});
  EXPECT_LT(report.dForceError, 1e-8) << report.describe();
}

TEST(SpringForceField, ForceIsMinusEnergyGradient) {
  SceneHolder s;
  ASSERT_TRUE(s.load(kFourPoints));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  const Eigen::VectorXd fd = check.finiteDifferenceForce();
  EXPECT_LT((f - fd).cwiseAbs().maxCoeff(), 1e-6 * scaleOf(f)) << f.transpose() << "\n"
                                                               << fd.transpose();
  // Internal forces: no net force.
  Vec3d total = Vec3d::Zero();
  for (Eigen::Index i = 0; i < f.size(); i += 3) total += f.segment<3>(i);
  EXPECT_LT(total.norm(), 1e-12);
}

TEST(SpringForceField, TangentStiffnessMatchesFiniteDifferences) {
  SceneHolder s;
  ASSERT_TRUE(s.load(kFourPoints));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::MatrixXd fd = check.finiteDifferenceStiffness();
  const Eigen::MatrixXd matrixFree = check.matrixFreeStiffness();
  const Eigen::MatrixXd assembled = check.assembled(0, 0, 1);
  const double scale = scaleOf(fd);
  EXPECT_LT((matrixFree - fd).cwiseAbs().maxCoeff(), 1e-6 * scale) << matrixFree << "\n\n" << fd;
  EXPECT_LT((assembled - fd).cwiseAbs().maxCoeff(), 1e-6 * scale);
  EXPECT_LT((assembled - assembled.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

TEST(SpringForceField, RigidMotionGivesNoForce) {
  // Springs at rest in a reference shape, then the shape rotated and translated.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3d(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3d t(3, -1, 2);
  const std::vector<Vec3d> reference{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 1.5}};
  std::string positions, springs;
  for (const Vec3d& p : reference) {
    const Vec3d q = R * p + t;
    positions +=
        std::to_string(q.x()) + " " + std::to_string(q.y()) + " " + std::to_string(q.z()) + "  ";
  }
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      springs += std::to_string(i) + " " + std::to_string(j) + " 1000 0 " +
                 std::to_string((reference[i] - reference[j]).norm()) + "  ";
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node gravity="0 0 0"><MechanicalObject position=")" + positions +
                     R"("/><SpringForceField spring=")" + springs + R"("/></Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  // std::to_string keeps 6 decimals: forces of order k * 1e-6.
  EXPECT_LT(check.force().cwiseAbs().maxCoeff(), 1000 * 2e-6);
  // At rest the stiffness has the six rigid modes in its null space.
  const Eigen::MatrixXd K = check.assembled(0, 0, 1);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(-K);
  int zeros = 0;
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i)
    if (std::abs(eig.eigenvalues()[i]) < 1e-2) ++zeros;
  EXPECT_EQ(zeros, 6) << eig.eigenvalues().transpose();
  EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-2);  // -K positive semi-definite at rest
}

TEST(SpringForceField, InteractionBetweenTwoStates) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <Node name="A"><MechanicalObject name="dofs" position="0 0 0  1 0.2 0"/></Node>
  <Node name="B"><MechanicalObject name="dofs" position="0.1 1.2 0.3  1.4 1 -0.2  2 2 2"/></Node>
  <SpringForceField name="links" object1="@A/dofs" object2="@B" spring="0 0 300 0 1  1 1 200 0 0.5  1 2 50 0 2"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  ASSERT_EQ(check.size(), 15u);
  const Eigen::MatrixXd fd = check.finiteDifferenceStiffness();
  const double scale = scaleOf(fd);
  EXPECT_LT((check.matrixFreeStiffness() - fd).cwiseAbs().maxCoeff(), 1e-6 * scale);
  // The assembled path puts each state's blocks at its own rows (offsets 0 and 6).
  EXPECT_LT((check.assembled(0, 0, 1) - fd).cwiseAbs().maxCoeff(), 1e-6 * scale);
  const Eigen::VectorXd f = check.force();
  EXPECT_LT((f - check.finiteDifferenceForce()).cwiseAbs().maxCoeff(), 1e-6 * scaleOf(f));
}

TEST(SpringForceField, DampingAlongTheSpring) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node gravity="0 0 0">
  <MechanicalObject position="0 0 0  2 0 0" velocity="0 0 0  -3 4 0"/>
  <SpringForceField spring="0 1 10 7 2"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  // At rest length, only damping: kd ((v2 - v1).e) e = 7 * -3 along x on point 0.
  const Eigen::VectorXd f = check.force();
  EXPECT_NEAR(f[0], -21, 1e-12);
  EXPECT_NEAR(f[1], 0, 1e-12);
  EXPECT_NEAR(f[3], 21, 1e-12);
  // B = df/dv = kd e e^T on the (0, 1) block.
  const Eigen::MatrixXd B = check.matrixFreeStiffness(1.0) - check.matrixFreeStiffness(0.0);
  EXPECT_NEAR(B(0, 3), 7, 1e-12);
  EXPECT_NEAR(B(0, 0), -7, 1e-12);
  EXPECT_NEAR(B(1, 4), 0, 1e-12);
}

TEST(SpringForceField, HangingMassReachesAnalyticElongation) {
  // A point of mass 2 kg under a fixed one, k = 500 N/m, L = 1: equilibrium at L + m g / k.
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 -9.81 0" dt="0.01">
  <EulerImplicitSolver rayleighMass="0.5" rayleighStiffness="0.1"/>
  <CGLinearSolver iterations="100" tolerance="1e-12" threshold="0"/>
  <MechanicalObject name="dofs" position="0 0 0  0 -1 0"/>
  <UniformMass vertexMass="2"/>
  <FixedProjectiveConstraint indices="0"/>
  <StiffSpringForceField spring="0 1 500 2 1"/>
</Node>)"));
  ASSERT_TRUE(s.step(2000));
  const auto x = numbers(s.text("@dofs.position"));
  EXPECT_NEAR(x[4], -(1 + 2 * 9.81 / 500), 1e-6);
  EXPECT_NEAR(x[3], 0, 1e-12);
}

TEST(SpringForceField, MalformedSpringListIsAnError) {
  SceneHolder s;
  s.loadFailing(R"(<Node><MechanicalObject position="0 0 0  1 0 0"/>
<SpringForceField spring="0 1 100 5 1  1 0 100 5"/></Node>)",
                {"spring", "5 numbers per spring", "got 9"});
  SceneHolder t;
  t.loadFailing(R"(<Node><MechanicalObject position="0 0 0  1 0 0"/>
<SpringForceField spring="0 x 100 5 1"/></Node>)",
                {"spring 0", "expected an integer, got 'x'"});
  SceneHolder u;
  u.loadFailing(R"(<Node><MechanicalObject position="0 0 0  1 0 0"/>
<SpringForceField spring="0 1 -100 5 1"/></Node>)",
                {"spring 0", ">= 0"});
}

TEST(SpringForceField, IndicesOutOfRangeAreNamed) {
  SceneHolder s;
  const Message m = s.loadFailing(R"(
<Node name="root">
  <Node name="A"><MechanicalObject name="dofs" position="0 0 0  1 0 0"/></Node>
  <Node name="B"><MechanicalObject name="dofs" position="0 1 0"/></Node>
  <SpringForceField object1="@A/dofs" object2="@B/dofs" spring="0 0 1 0 1  2 0 1 0 1  1 3 1 0 1"/>
</Node>)",
                                  {"2 springs with indices out of range", "spring 1 (2 0)",
                                   "index1 2 >= 2 points of /root/A/dofs", "spring 2 (1 3)",
                                   "index2 3 >= 1 points of /root/B/dofs"});
  EXPECT_EQ(m.field, "spring");
  SceneHolder t;
  t.loadFailing(R"(<Node><Node name="A"><MechanicalObject name="dofs" position="0 0 0"/></Node>
<SpringForceField object1="@A/dofs" spring="0 0 1 0 1"/></Node>)",
                {"give both object1 and object2"});
}

TEST(SpringForceField, SpringsFromIndices) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node gravity="0 0 0">
  <MechanicalObject position="0 0 0  2 0 0  0 3 0"/>
  <SpringForceField stiffness="10" damping="0" indices1="0 0" indices2="1 2" lengths="1"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  // Spring 0-1 stretched by 1, spring 0-2 by 2: f0 = 10 * (1, 2, 0).
  EXPECT_NEAR(f[0], 10, 1e-12);
  EXPECT_NEAR(f[1], 20, 1e-12);
  EXPECT_NEAR(check.energy(), 0.5 * 10 * (1 + 4), 1e-12);
}

}  // namespace
}  // namespace stroma::test
