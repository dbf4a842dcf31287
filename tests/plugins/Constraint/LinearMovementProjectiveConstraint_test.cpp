// SPDX-License-Identifier: MIT
// LinearMovementProjectiveConstraint: the key displacements at the key times, linear
// interpolation between them, mean velocities, the window of activity, rigid frames, and bad
// input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma::test {
namespace {

// Point 1 follows 0 -> (1,0,0) at t=1 -> (1,2,0) at t=3, under gravity; point 0 is free.
std::string pointScene(double dt) {
  return R"(
<Node name="root" gravity="0 -10 0" dt=")" +
         std::to_string(dt) + R"(">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>
  <MechanicalObject name="dofs" position="0 0 0  5 6 7"/>
  <UniformMass vertexMass="1"/>
  <SpringForceField spring="0 1 10 0 1"/>
  <LinearMovementProjectiveConstraint name="move" indices="1" keyTimes="0 1 3"
                                      movements="0 0 0  1 0 0  1 2 0"/>
</Node>)";
}

Vec3d point(SceneHolder& s, int i) {
  const auto x = numbers(s.text("@dofs.position"));
  return {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
}
Vec3d velocity(SceneHolder& s, int i) {
  const auto v = numbers(s.text("@dofs.velocity"));
  return {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
}

TEST(LinearMovementProjectiveConstraint, ReachesTheKeyDisplacementsAtTheKeyTimes) {
  SceneHolder s;
  ASSERT_TRUE(s.load(pointScene(0.25)));
  const Vec3d x0(5, 6, 7);
  ASSERT_TRUE(s.step(4));  // t = 1
  EXPECT_LT((point(s, 1) - (x0 + Vec3d(1, 0, 0))).norm(), 1e-12) << point(s, 1).transpose();
  EXPECT_LT((velocity(s, 1) - Vec3d(1, 0, 0)).norm(), 1e-12);
  ASSERT_TRUE(s.step(8));  // t = 3
  EXPECT_LT((point(s, 1) - (x0 + Vec3d(1, 2, 0))).norm(), 1e-12);
  EXPECT_LT((velocity(s, 1) - Vec3d(0, 1, 0)).norm(), 1e-12);
  // The free point moved under gravity and the spring.
  EXPECT_GT((point(s, 0) - Vec3d::Zero()).norm(), 1.0);
}

TEST(LinearMovementProjectiveConstraint, InterpolatesBetweenKeyTimes) {
  SceneHolder s;
  ASSERT_TRUE(s.load(pointScene(0.1)));
  const Vec3d x0(5, 6, 7);
  ASSERT_TRUE(s.step(3));  // t = 0.3
  EXPECT_LT((point(s, 1) - (x0 + Vec3d(0.3, 0, 0))).norm(), 1e-12);
  ASSERT_TRUE(s.step(14));  // t = 1.7: (1, 2 * 0.7 / 2, 0)
  EXPECT_LT((point(s, 1) - (x0 + Vec3d(1, 0.7, 0))).norm(), 1e-12);
}

TEST(LinearMovementProjectiveConstraint, MeanVelocityAcrossAKeyTime) {
  // dt = 0.4: the step from 0.8 to 1.2 crosses t = 1; the velocity is the mean over the step.
  SceneHolder s;
  ASSERT_TRUE(s.load(pointScene(0.4)));
  ASSERT_TRUE(s.step(3));  // t = 1.2
  const Vec3d x0(5, 6, 7);
  EXPECT_LT((point(s, 1) - (x0 + Vec3d(1, 0.2, 0))).norm(), 1e-12);
  EXPECT_LT((velocity(s, 1) - Vec3d(0.2, 0.2, 0) / 0.4).norm(), 1e-12);
}

TEST(LinearMovementProjectiveConstraint, ActiveOnlyBetweenFirstAndLastKeyTimes) {
  SceneHolder s;
  ASSERT_TRUE(s.load(pointScene(0.5)));
  auto* move = s.get<BaseProjectiveConstraint>("@move");
  ASSERT_NE(move, nullptr);
  std::vector<std::size_t> rows;
  move->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{3, 4, 5}));
  ASSERT_TRUE(s.step(6));  // t = 3: from the last key time on, the point is free (as SOFA)
  rows.clear();
  move->fixedRows(rows);
  EXPECT_TRUE(rows.empty());
  const Vec3d before = point(s, 1);
  ASSERT_TRUE(s.step(1));
  EXPECT_GT((point(s, 1) - before).norm(), 1e-3);
}

TEST(LinearMovementProjectiveConstraint, RigidFrameTranslatesAndTurns) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 -10 0" dt="0.125">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>
  <MechanicalObject template="Rigid3" name="frame" position="1 0 0  0 0 0 1"/>
  <UniformMass vertexMass="1"/>
  <LinearMovementProjectiveConstraint template="Rigid3" keyTimes="0 1 2"
      movements="0 0 0 0 0 0   2 0 0 0 0 1.5707963267948966   2 0 0 0 0 1.5707963267948966"/>
</Node>)"));
  ASSERT_TRUE(s.step(4));  // t = 0.5: half the way, 45 degrees about z
  auto x = numbers(s.text("@frame.position"));
  auto v = numbers(s.text("@frame.velocity"));
  EXPECT_NEAR(x[0], 2, 1e-12);
  EXPECT_NEAR(x[1], 0, 1e-12);
  const Quat q(x[6], x[3], x[4], x[5]);
  EXPECT_NEAR(q.angularDistance(Quat(Eigen::AngleAxisd(M_PI / 4, Vec3d::UnitZ()))), 0, 1e-12);
  EXPECT_NEAR(v[0], 2, 1e-12);
  EXPECT_NEAR(v[5], M_PI / 2, 1e-9);
  ASSERT_TRUE(s.step(4));  // t = 1
  x = numbers(s.text("@frame.position"));
  EXPECT_NEAR(x[0], 3, 1e-12);
  EXPECT_NEAR(Quat(x[6], x[3], x[4], x[5])
                  .angularDistance(Quat(Eigen::AngleAxisd(M_PI / 2, Vec3d::UnitZ()))),
              0, 1e-12);
  ASSERT_TRUE(s.step(4));  // t = 1.5: held (equal movements), no velocity
  v = numbers(s.text("@frame.velocity"));
  EXPECT_LT(Eigen::Map<Eigen::VectorXd>(v.data(), 6).norm(), 1e-12);
}

TEST(LinearMovementProjectiveConstraint, BadInputIsReported) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<LinearMovementProjectiveConstraint indices="0" keyTimes="0 1 2" movements="0 0 0 1 1 1"/></Node>)",
                          {"2 movements for 3 key times"})
                .field,
            "movements");
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<LinearMovementProjectiveConstraint indices="0" keyTimes="0 2 1" movements="0 0 0 1 1 1 2 2 2"/></Node>)",
                          {"increasing order", "keyTimes[2]"})
                .field,
            "keyTimes");
  SceneHolder u;
  EXPECT_EQ(u.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<LinearMovementProjectiveConstraint indices="0 4" keyTimes="0 1" movements="0 0 0 1 1 1"/></Node>)",
                          {"1 index out of range", ": 4"})
                .field,
            "indices");
}

}  // namespace
}  // namespace stroma::test
