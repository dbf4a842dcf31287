// SPDX-License-Identifier: MIT
// UniformMass for points and rigid frames: the mass matrix (assembled and applied), gravity,
// kinetic energy, free fall against the exact backward Euler solution, and bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/Node.h"
#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/Mass.h"

namespace stroma::test {
namespace {

/// The assembled m M + k K of the root's system, as a dense matrix.
Eigen::MatrixXd assembledMass(Scene& scene) {
  MechanicalOperations mop(scene.root(), scene.timing());
  MechanicalParams mp;
  mp.mFactor = 1;
  mp.kFactor = 0;
  AssembledMatrix A;
  mop.assemble(mp, A);
  return Eigen::MatrixXd(A.matrix());
}

/// M applied to each unit vector (computeMBKdx), as a dense matrix.
Eigen::MatrixXd appliedMass(Scene& scene) {
  MechanicalOperations mop(scene.root(), scene.timing());
  const auto n = static_cast<Eigen::Index>(mop.systemSize());
  Eigen::MatrixXd M(n, n);
  const VecId dx = mop.allocDeriv(), out = mop.allocDeriv();
  MechanicalParams mp;
  mp.mFactor = 1;
  mp.kFactor = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    mop.scatter(Eigen::VectorXd::Unit(n, j), dx);
    mop.computeMBKdx(mp, out, dx);
    Eigen::VectorXd column;
    mop.gather(out, column);
    M.col(j) = column;
  }
  return M;
}

TEST(UniformMass, TotalMassIsSpreadOverThePoints) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node gravity="0 -10 0"><MechanicalObject position="0 0 0 1 0 0 2 0 0"/>
<UniformMass totalMass="6"/></Node>)"));
  const Eigen::MatrixXd M = assembledMass(s.scene());
  EXPECT_TRUE(M.isApprox(2 * Eigen::MatrixXd::Identity(9, 9)));
  EXPECT_TRUE(appliedMass(s.scene()).isApprox(M));
  // Gravity: m g on each point; potential energy -sum m g.x.
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(f[3 * i + 1], -20);
  EXPECT_LT((check.finiteDifferenceForce() - f).norm(), 1e-6);
}

TEST(UniformMass, FreeFallIsTheExactBackwardEulerSolution) {
  // Backward Euler with a constant force: v_n = n h g, x_n = x_0 + h^2 g n (n + 1) / 2.
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node gravity="0 -9.81 0" dt="0.01">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="50" tolerance="1e-14" threshold="0"/>
  <MechanicalObject name="dofs" position="0 1 0  2 3 4"/>
  <UniformMass vertexMass="0.3"/>
</Node>)"));
  const int n = 50;
  ASSERT_TRUE(s.step(n));
  const double h = 0.01, g = -9.81;
  const auto x = numbers(s.text("@dofs.position"));
  const auto v = numbers(s.text("@dofs.velocity"));
  EXPECT_NEAR(x[1], 1 + h * h * g * n * (n + 1) / 2, 1e-12);
  EXPECT_NEAR(x[4], 3 + h * h * g * n * (n + 1) / 2, 1e-12);
  EXPECT_NEAR(x[3], 2, 1e-15);
  EXPECT_NEAR(v[1], n * h * g, 1e-12);
}

// A frame turned by 90 degrees about z, mass 2, inertia per unit mass diag(1, 2, 3).
const char* kRigidFrame = R"(
<Node name="root" gravity="0 0 -10" dt="0.01">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="50" tolerance="1e-14" threshold="0"/>
  <MechanicalObject template="Rigid3" name="frame" position="1 2 3  0 0 0.7071067811865476 0.7071067811865476"
                    velocity="0 0 0  0 0 0.5"/>
  <UniformMass name="mass" vertexMass="2 1 [1 0 0,0 2 0,0 0 3]"/>
</Node>)";

TEST(UniformMass, RigidMassMatrixHoldsTheWorldInertia) {
  SceneHolder s;
  ASSERT_TRUE(s.load(kRigidFrame));
  const Eigen::MatrixXd M = assembledMass(s.scene());
  // Body x maps to world y: world inertia m R J R^T = 2 diag(2, 1, 3).
  Eigen::VectorXd expected(6);
  expected << 2, 2, 2, 4, 2, 6;
  EXPECT_LT((M - Eigen::MatrixXd(expected.asDiagonal())).cwiseAbs().maxCoeff(), 1e-12) << M;
  EXPECT_LT((appliedMass(s.scene()) - M).cwiseAbs().maxCoeff(), 1e-12);
  // Kinetic energy w.(I w) / 2 = 6 * 0.25 / 2.
  MechanicalOperations mop(s.root(), s.scene().timing());
  EXPECT_NEAR(mop.kineticEnergy(), 0.75, 1e-12);
  // The same mass from 11 numbers, and from the mass alone (identity inertia).
  SceneHolder t;
  ASSERT_TRUE(t.load(R"(<Node><MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1"/>
<UniformMass vertexMass="3 1 0.5 0 0 0 0.5 0 0 0 0.5"/></Node>)"));
  EXPECT_TRUE(assembledMass(t.scene()).diagonal().isApprox(
      (Eigen::VectorXd(6) << 3, 3, 3, 1.5, 1.5, 1.5).finished()));
}

TEST(UniformMass, RigidFrameFallsAndKeepsSpinning) {
  SceneHolder s;
  ASSERT_TRUE(s.load(kRigidFrame));
  const int n = 40;
  ASSERT_TRUE(s.step(n));
  const auto x = numbers(s.text("@frame.position"));
  const auto v = numbers(s.text("@frame.velocity"));
  const double h = 0.01;
  EXPECT_NEAR(x[0], 1, 1e-14);
  EXPECT_NEAR(x[2], 3 - 10 * h * h * n * (n + 1) / 2, 1e-11);
  EXPECT_NEAR(v[2], -10 * h * n, 1e-11);
  // No torque: the spin about the principal axis z stays, the angle grows by h w per step.
  EXPECT_NEAR(v[5], 0.5, 1e-12);
  const Quat q(x[6], x[3], x[4], x[5]);
  const double angle = 2 * std::atan2(q.z(), q.w());
  EXPECT_NEAR(angle, M_PI / 2 + n * h * 0.5, 1e-9);
}

TEST(UniformMass, BadInputIsReported) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1"/>
<UniformMass vertexMass="1 2 3"/></Node>)",
                          {"expected 1 (mass), 2 (mass volume) or 11", "got 3"})
                .field,
            "vertexMass");
  SceneHolder t;
  const Message m = t.loadFailing(R"(<Node><MechanicalObject position="0 0 0 1 1 1"/>
<UniformMass indices="0 1 2 7"/></Node>)",
                                  {"2 indices out of range of the 2 points: 2 7"});
  EXPECT_EQ(m.field, "indices");
  SceneHolder u;
  u.loadFailing(R"(<Node><MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1"/>
<UniformMass vertexMass="1 1 1 0 0 0 -1 0 0 0 1"/></Node>)",
                {"positive definite"});
  SceneHolder w;
  EXPECT_EQ(
      w.loadFailing(
           R"(<Node><MechanicalObject position="0 0 0"/><UniformMass vertexMass="-1"/></Node>)",
           {"expected a value >= 0, got -1"})
          .field,
      "vertexMass");
}

TEST(UniformMass, MassChangedWhileRunningActsAtTheNextStep) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node gravity="0 -10 0"><MechanicalObject position="0 0 0"/>
<UniformMass name="mass" vertexMass="1"/></Node>)"));
  EXPECT_DOUBLE_EQ(assembledMass(s.scene())(0, 0), 1);
  s.set("@mass.vertexMass", "4");
  EXPECT_DOUBLE_EQ(assembledMass(s.scene())(0, 0), 4);
  s.set("@mass.totalMass", "9");
  EXPECT_DOUBLE_EQ(assembledMass(s.scene())(0, 0), 9);
}

TEST(UniformMass, PointsInAPlaneOrOnALineTakeTheFirstComponentsOfGravity) {
  // As SOFA: a Vec2d state feels (gx, gy), a Vec1d state gx.
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="1 -2 3">
  <Node name="plane">
    <MechanicalObject template="Vec2" name="dofs" position="0 0  1 1"/>
    <UniformMass vertexMass="0.5"/>
  </Node>
  <Node name="line">
    <MechanicalObject template="Vec1" name="dofs" position="0 2 5"/>
    <UniformMass totalMass="3"/>
  </Node>
</Node>)"));
  MechanicalOperations mop(s.root(), s.scene().timing());
  mop.computeForce(MechanicalParams{}, VecId::force());
  EXPECT_EQ(s.text("@plane/dofs.force"), "0.5 -1 0.5 -1");
  EXPECT_EQ(s.text("@line/dofs.force"), "1 1 1");
  // E = -sum m g.x: plane -0.5 (1 - 2), line -1 (0 + 2 + 5).
  EXPECT_DOUBLE_EQ(mop.potentialEnergy(MechanicalParams{}), 0.5 - 7);
  const Eigen::MatrixXd M = assembledMass(s.scene());
  ASSERT_EQ(M.rows(), 2 * 2 + 3);
  EXPECT_TRUE(M.isDiagonal());
  EXPECT_DOUBLE_EQ(M.trace(), 4 * 0.5 + 3 * 1.0);
  EXPECT_TRUE(M.isApprox(appliedMass(s.scene())));
}

}  // namespace
}  // namespace stroma::test
