// SPDX-License-Identifier: MIT
// TrianglePressureForceField: the forces on a flat square sum to pressure times its area, a
// third of each triangle's share on each of its vertices; a free plate's centre of mass
// accelerates at p A / M; the state and topology may be in a parent node (SOFA's scenes); the
// triangles a topology loses are dropped, the others kept through the renumbering; with
// useConstantForce="0" the load follows the current area and its stiffness matches finite
// differences (generic force-field test, as for the constant load); bad input is reported.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/ForceField.h"
#include "support/AllocationCounter.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

// A square of side 2 in the plane z = 0 (area 4), two triangles sharing the diagonal 0-2; the
// state in the root, the triangles in a child node, as SOFA's scenes have them.
std::string squareScene(const std::string& pressure, const std::string& extra = "",
                        const std::string& position = "0 0 0  2 0 0  2 2 0  0 2 0") {
  return R"(<Node name="root" gravity="0 0 0" dt="0.01">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>
  <MechanicalObject name="dofs" position=")" +
         position + R"(" rest_position="0 0 0  2 0 0  2 2 0  0 2 0"/>
  <UniformMass totalMass="8"/>
  <Node name="surface">
    <TriangleSetTopologyContainer name="triangles" triangles="0 1 2  0 2 3"/>
    <TrianglePressureForceField name="pressure" triangleList="0 1" pressure=")" +
         pressure + "\" " + extra + R"(/>
  </Node>
</Node>)";
}

Eigen::VectorXd forceOf(SceneHolder& s) {
  ForceFieldChecker check(s.scene(), s.root());
  return check.force();
}

TEST(TrianglePressureForceField, TotalForceIsPressureTimesArea) {
  SceneHolder s;
  ASSERT_TRUE(s.load(squareScene("0.5 -1 3")));
  const Eigen::VectorXd f = forceOf(s);
  ASSERT_EQ(f.size(), 12);
  const Vec3d p(0.5, -1, 3);
  Vec3d total = Vec3d::Zero();
  for (int i = 0; i < 4; ++i) total += f.segment<3>(3 * i);
  EXPECT_LT((total - 4.0 * p).norm(), 1e-14);  // p A, A = 4
  // Each triangle (area 2) gives 2 p / 3 to each of its vertices: 0 and 2 are in both.
  EXPECT_LT((Vec3d(f.segment<3>(0)) - 4.0 / 3 * p).norm(), 1e-14);
  EXPECT_LT((Vec3d(f.segment<3>(3)) - 2.0 / 3 * p).norm(), 1e-14);
  EXPECT_LT((Vec3d(f.segment<3>(6)) - 4.0 / 3 * p).norm(), 1e-14);
}

TEST(TrianglePressureForceField, FreePlateAcceleratesAtPressureTimesAreaOverMass) {
  // Backward Euler with a constant force: the centre of mass moves by h^2 n (n + 1) / 2 p A / M.
  SceneHolder s;
  ASSERT_TRUE(s.load(squareScene("0 0 2")));
  const int n = 10;
  ASSERT_TRUE(s.step(n));
  const auto x = numbers(s.text("@dofs.position"));
  double zMean = 0;
  for (int i = 0; i < 4; ++i) zMean += x[3 * i + 2] / 4;
  EXPECT_NEAR(zMean, 1e-4 * n * (n + 1) / 2.0 * 2.0 * 4 / 8, 1e-14);
}

TEST(TrianglePressureForceField, ConstantForceUsesTheRestAreaCurrentAreaFollowsTheSurface) {
  // The square stretched to 3 x 2 (area 6) in its current positions.
  const std::string stretched = "0 0 0  3 0 0  3 2 0  0 2 0";
  SceneHolder s;
  ASSERT_TRUE(s.load(squareScene("0 0 1", "", stretched)));
  EXPECT_NEAR(forceOf(s).sum(), 4, 1e-14);
  SceneHolder t;
  ASSERT_TRUE(t.load(squareScene("0 0 1", R"(useConstantForce="0")", stretched)));
  EXPECT_NEAR(forceOf(t).sum(), 6, 1e-14);
}

TEST(TrianglePressureForceField, TrianglesTheTopologyLosesAreDropped) {
  SceneHolder s;
  ASSERT_TRUE(s.load(squareScene("0 0 1")));
  EXPECT_NEAR(forceOf(s).sum(), 4, 1e-14);
  // The first triangle removed: the second one is now triangle 0, and still loaded.
  s.set("@surface/triangles.triangles", "0 2 3");
  const Eigen::VectorXd f = forceOf(s);
  EXPECT_NEAR(f.sum(), 2, 1e-14);
  EXPECT_EQ(f[5], 0);                  // point 1 (z: f[5]) is no longer loaded
  EXPECT_NEAR(f[11], 2.0 / 3, 1e-14);  // point 3 is, a third of p A = 2
  // Renumbered without loss: the loaded triangle (0 1 2), now triangle 1, stays loaded.
  std::string xml = squareScene("0 0 1");
  xml.replace(xml.find(R"(triangleList="0 1")"), 18, R"(triangleList="0")");
  SceneHolder t;
  ASSERT_TRUE(t.load(xml));
  t.set("@surface/triangles.triangles", "0 2 3  0 1 2");
  const Eigen::VectorXd g = forceOf(t);
  EXPECT_NEAR(g[5], 2.0 / 3, 1e-14);
  EXPECT_EQ(g[11], 0);
  for (SceneHolder* h : {&s, &t})
    for (const Message& m : h->scene().log().messages())
      EXPECT_TRUE(m.level != MessageLevel::warning && m.level != MessageLevel::error)
          << formatForConsole(m);
}

TEST(TrianglePressureForceField, PassesTheForceFieldTest) {
  const std::string tilted = "0 0 0.1  2 0 -0.2  2.1 2 0  0 1.9 0.3";
  // The constant load: energy -f.x, no stiffness.
  checkForceField(squareScene("0.3 -0.2 1", "", tilted),
                  {.forceField = "/root/surface/pressure", .zeroAtRest = false});
  // The load following the current area: not conservative, K = p (grad A)^T / 3.
  checkForceField(squareScene("0.3 -0.2 1", R"(useConstantForce="0")", tilted),
                  {.forceField = "/root/surface/pressure",
                   .hasEnergy = false,
                   .conservative = false,
                   .zeroAtRest = false});
}

TEST(TrianglePressureForceField, WarmForceAndStiffnessAllocateNothing) {
  SceneHolder s;
  ASSERT_TRUE(s.load(squareScene("0.3 -0.2 1", R"(useConstantForce="0")",
                                 "0 0 0.1  2 0 -0.2  2.1 2 0  0 1.9 0.3")));
  auto* field = s.get<BaseForceField>("@surface/pressure");
  ASSERT_NE(field, nullptr);
  MechanicalParams mp;
  mp.kFactor = 1;
  StateOffsets offsets;
  offsets.set(s.get<BaseMechanicalState>("@dofs"), 0);
  AssembledMatrix matrix;
  for (int pass = 0; pass < 2; ++pass) {  // the first pass records the pattern
    matrix.begin(12);
    g_allocations = 0;
    g_counting = pass == 1;
    field->accumulateForce(mp, VecId::force());
    field->accumulateDForce(mp, VecId::force(), VecId::velocity());
    field->accumulateKMatrix(mp, matrix, offsets);
    g_counting = false;
    matrix.finish();
  }
  EXPECT_EQ(g_allocations, 0);
}

TEST(TrianglePressureForceField, BadInputIsReported) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject position="0 0 0  1 0 0  0 1 0"/>
  <TriangleSetTopologyContainer triangles="0 1 2"/>
  <TrianglePressureForceField triangleList="0 3" pressure="1 0 0"/></Node>)",
                          {"1 index out of range of the 1 triangles", "3"})
                .field,
            "triangleList");
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(R"(<Node><MechanicalObject position="0 0 0  1 0 0"/>
  <TriangleSetTopologyContainer triangles="0 1 2"/>
  <TrianglePressureForceField triangleList="0" pressure="1 0 0"/></Node>)",
                          {"use points out of range of the 2 points"})
                .field,
            "topology");
  SceneHolder u;
  EXPECT_EQ(u.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
  <TrianglePressureForceField triangleList="0" pressure="1 0 0"/></Node>)",
                          {"needs a topology"})
                .field,
            "topology");
}

}  // namespace
}  // namespace stroma::test
