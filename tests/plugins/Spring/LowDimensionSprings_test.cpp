// SPDX-License-Identifier: MIT
// Springs between points on a line (Vec1d) and in a plane (Vec2d): a 1-D chain under gravity at
// its analytic static equilibrium (direct and matrix-free solvers), the generic force-field test
// on 1-D and 2-D meshes of springs and on SpringForceField, and no force under an in-plane rigid
// motion of a 2-D mesh.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

// A vertical chain on a line: n points of mass m, spacing L, the first one fixed, gravity g
// along the line, MeshSpringForceField of stiffness per unit length `stiffness` on the edges of
// a 1-D grid. Every spring then has ks = stiffness / L.
constexpr int kChainPoints = 6;
constexpr double kSpacing = 0.5, kPointMass = 0.3, kStiffness = 40, kGravity = 9.81;

std::string chainScene(const std::string& solvers) {
  const double length = kSpacing * (kChainPoints - 1);
  return R"(<Node name="root" gravity=")" + std::to_string(kGravity) + R"( 0 0" dt="0.05">
  )" + solvers +
         R"(
  <RegularGridTopology name="grid" nx=")" +
         std::to_string(kChainPoints) + R"(" ny="1" nz="1" xmin="0" xmax=")" +
         std::to_string(length) + R"(" ymin="0" ymax="0" zmin="0" zmax="0"/>
  <MechanicalObject template="Vec1" name="dofs"/>
  <UniformMass vertexMass=")" +
         std::to_string(kPointMass) + R"("/>
  <FixedProjectiveConstraint indices="0"/>
  <MeshSpringForceField name="springs" stiffness=")" +
         std::to_string(kStiffness) + R"("/>
</Node>)";
}

// Static equilibrium: the spring from point i to i + 1 carries the weight of the points below
// it, (n - 1 - i) m g, and stretches by that over ks = stiffness / L.
std::vector<double> chainEquilibrium() {
  std::vector<double> x(kChainPoints);
  const double ks = kStiffness / kSpacing;
  for (int i = 1; i < kChainPoints; ++i)
    x[i] = x[i - 1] + kSpacing + (kChainPoints - i) * kPointMass * kGravity / ks;
  return x;
}

void expectChainAtEquilibrium(SceneHolder& s, double tolerance) {
  const auto x = numbers(s.text("@dofs.position"));
  const auto expected = chainEquilibrium();
  ASSERT_EQ(x.size(), expected.size()) << "one coordinate per point";
  EXPECT_EQ(x[0], 0.0) << "the fixed point stays put";
  for (int i = 1; i < kChainPoints; ++i) EXPECT_NEAR(x[i], expected[i], tolerance) << "point " << i;
}

TEST(LowDimensionSprings, ChainOnALineReachesTheStaticEquilibrium) {
  // The springs of a chain on a line are linear (e = +1 throughout): one Newton step is exact.
  SceneHolder s;
  ASSERT_TRUE(s.load(chainScene(R"(<StaticSolver/> <SparseLDLSolver/>)")));
  ASSERT_TRUE(s.step(1));
  expectChainAtEquilibrium(s, 1e-10);
}

TEST(LowDimensionSprings, DampedImplicitRunOnALineSettlesAtTheStaticEquilibrium) {
  // Matrix-free path (CG through addDForce), heavily damped: the motion dies out at the same
  // equilibrium. The slowest mode decays as exp(-t rayleighMass / 2) at worst: 2000 steps of
  // 0.05 s leave far less than the tolerance.
  SceneHolder s;
  ASSERT_TRUE(s.load(chainScene(
      R"(<EulerImplicitSolver rayleighMass="1" rayleighStiffness="0.05"/>
  <CGLinearSolver iterations="100" tolerance="1e-12" threshold="0"/>)")));
  ASSERT_TRUE(s.step(2000));
  expectChainAtEquilibrium(s, 1e-8);
  for (double v : numbers(s.text("@dofs.velocity"))) EXPECT_NEAR(v, 0, 1e-8);
}

// A 4 x 3 grid of quads in the plane, springs on the edges and the diagonals.
const char* kPlaneGrid = R"(<Node name="root" gravity="0 0 0">
  <RegularGridTopology name="grid" n="4 3 1" min="0 0 0" max="3 2 0"/>
  <MechanicalObject template="Vec2" name="dofs"/>
  <MeshSpringForceField name="springs" stiffness="150" damping="3"/>
</Node>)";

TEST(LowDimensionSprings, MeshSpringsInAPlanePassTheForceFieldTest) {
  // The rigid-motion check of the shared test moves Vec3d and Rigid3d states only: the in-plane
  // rigid motions are checked below.
  const auto report = checkForceField(kPlaneGrid);
  EXPECT_EQ(report.dofs, 12u * 2);
  EXPECT_GT(report.forceNorm, 0) << report.describe();
  EXPECT_GE(report.dampingError, 0) << report.describe();
}

TEST(LowDimensionSprings, TheSharedRigidMotionCheckRefusesPlanarStates) {
  // It would move nothing, and pass without checking anything.
  const auto report = measureForceField(kPlaneGrid, {.rotationInvariant = true});
  EXPECT_NE(report.failure.find("is a Vec2d state"), std::string::npos) << report.failure;
}

TEST(LowDimensionSprings, MeshSpringsOnALinePassTheForceFieldTest) {
  const auto report = checkForceField(R"(<Node name="root" gravity="0 0 0">
  <RegularGridTopology name="grid" nx="5" ny="1" nz="1" xmin="0" xmax="4" ymin="0" ymax="0"
                       zmin="0" zmax="0"/>
  <MechanicalObject template="Vec1" name="dofs"/>
  <MeshSpringForceField name="springs" stiffness="80" damping="2"/>
</Node>)");
  EXPECT_EQ(report.dofs, 5u);
  EXPECT_GT(report.forceNorm, 0) << report.describe();
}

TEST(LowDimensionSprings, SpringForceFieldInAPlanePassesTheForceFieldTest) {
  // Stretched, at rest, and of zero rest length (an attachment).
  checkForceField(R"(<Node name="root" gravity="0 0 0">
  <MechanicalObject template="Vec2" name="dofs" position="0 0  1 0  1 1  0 1"/>
  <SpringForceField name="springs"
      spring="0 1 100 2 1   1 2 250 0 1.2   2 3 80 1 0.7   0 2 60 0 0   1 3 40 0 1.4142135623730951"/>
</Node>)",
                  {.zeroAtRest = false});
}

TEST(LowDimensionSprings, InPlaneRigidMotionOfTheRestShapeGivesNoForce) {
  SceneHolder s;
  ASSERT_TRUE(s.load(kPlaneGrid));
  auto* state = s.get<MechanicalState<Vec2Types>>("@dofs");
  ASSERT_NE(state, nullptr);
  const Eigen::Rotation2Dd rotation(0.8);
  const Vec2d translation(4, -1.5);
  const auto rest = state->readCoord(VecId::restPosition());
  auto& x = state->writeCoord(VecId::position());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = rotation * rest[i] + translation;

  MechanicalOperations mop(s.root(), s.scene().timing());
  mop.computeForce(MechanicalParams{}, VecId::force());
  double largest = 0;
  for (const Vec2d& f : state->readDeriv(VecId::force())) largest = std::max(largest, f.norm());
  // Stiffnesses of order 100 N/m over unit lengths: round-off is ~1e-13 N.
  EXPECT_LT(largest, 1e-10);
}

}  // namespace
}  // namespace stroma::test
