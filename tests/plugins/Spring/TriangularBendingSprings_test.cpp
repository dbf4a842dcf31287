// SPDX-License-Identifier: MIT
// TriangularBendingSprings: one spring between the vertices opposite each interior edge (on the
// state above when its node has none), at rest on a flat sheet, the closed-form force of a
// folded pair (and SOFA's, measured), a damped implicit step against SOFA's, the generic
// force-field test, a hanging cloth whose total potential energy (gravity + springs) is
// stationary at rest and decreases monotonically under damping, a warm step that allocates
// nothing, and bad input.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/ForceField.h"
#include "support/AllocationCounter.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

/// An n x n grid of points on [0, size]^2 in the plane z = 0, two triangles per cell, as
/// MeshTopology triangles and MechanicalObject positions.
struct Sheet {
  std::string triangles, positions;
  int n = 0;
};
Sheet makeSheet(int n, double size) {
  Sheet s;
  s.n = n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      s.positions +=
          std::to_string(size * i / (n - 1)) + " " + std::to_string(size * j / (n - 1)) + " 0  ";
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = i + n * j, b = a + 1, c = a + n + 1, d = a + n;
      s.triangles += std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "  " +
                     std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "  ";
    }
  return s;
}

// Two triangles around the edge 0-2, flat at rest; 1 and 3 opposite the edge (2 apart).
const char* kPair = R"(
<Node name="root" gravity="0 0 0">
  <MeshTopology triangles="0 1 2  0 2 3"/>
  <MechanicalObject name="dofs" rest_position="0 0 0  1 -1 0  2 0 0  1 1 0"
                    position="0 0 0  1 -1 0.3  2 0 0  1 1 0.1"/>
  <TriangularBendingSprings name="bending" stiffness="300" damping="0"/>
</Node>)";

TEST(TriangularBendingSprings, FoldedPairGivesTheClosedFormSpringForce) {
  SceneHolder s;
  ASSERT_TRUE(s.load(kPair));
  // One spring, 1-3, rest length 2, the given stiffness (not per unit length).
  EXPECT_EQ(numbers(s.text("@bending.spring")), (std::vector<double>{1, 3, 300, 0, 2}));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  // f1 = ks (l - L) e, e = (x3 - x1) / l = (0, 2, -0.2) / l; f3 = -f1; the edge is unloaded.
  const double l = std::sqrt(4.04);
  const Vec3d f1 = 300 * (l - 2) * Vec3d(0, 2, -0.2) / l;
  EXPECT_LT((f.segment<3>(3) - f1).norm(), 1e-12);
  EXPECT_LT((f.segment<3>(9) + f1).norm(), 1e-12);
  EXPECT_EQ(f.segment<3>(0).norm() + f.segment<3>(6).norm(), 0.0);
  // SOFA (runSofa, one explicit step of unit mass and dt): f1 = (0, 2.97769, -0.297769).
  EXPECT_NEAR(f[4], 2.97769, 5e-6);
  EXPECT_NEAR(f[5], -0.297769, 5e-7);
  EXPECT_NEAR(check.energy(), 0.5 * 300 * (l - 2) * (l - 2), 1e-14);
}

TEST(TriangularBendingSprings, UnderATopologicalMappingActsOnTheStateAbove) {
  // As in SOFA's scenes: the triangles in a child node without a state (where a topological
  // mapping would put them), the springs on the parent's points.
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <MechanicalObject name="dofs" rest_position="0 0 0  1 -1 0  2 0 0  1 1 0"
                    position="0 0 0  1 -1 0.3  2 0 0  1 1 0.1"/>
  <Node name="T">
    <MeshTopology triangles="0 1 2  0 2 3"/>
    <TriangularBendingSprings name="bending" stiffness="300" damping="0"/>
  </Node>
</Node>)"));
  EXPECT_EQ(numbers(s.text("@T/bending.spring")), (std::vector<double>{1, 3, 300, 0, 2}));
  ForceFieldChecker check(s.scene(), s.root());
  EXPECT_NEAR(check.force()[4], 2.97769, 5e-6);  // SOFA's, as above
}

TEST(TriangularBendingSprings, ImplicitStepWithDampingMatchesSofa) {
  // A fan of four triangles around point 0, three springs (one compressed, two stretched),
  // moving: one backward Euler step. The tangent holds the damping force in its geometric term,
  // (ks (l - L) + kd (v2 - v1).e) / l, as SOFA's: without it the velocities part by 7e-3.
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0" dt="0.1">
  <EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
  <SparseLDLSolver/>
  <MeshTopology triangles="0 1 2  0 2 3  0 3 4  0 4 5"/>
  <MechanicalObject name="dofs" rest_position="0 0 0  2 -1 0  2 0.5 0  1.2 1.8 0  -0.5 2 0  -1.8 0.8 0"
      position="0 0 0.1  2 -1 0.3  2.1 0.5 0  1.2 1.6 0.4  -0.4 2 -0.1  -1.9 0.7 0.2"
      velocity="0 0 0  0.3 0.1 -0.2  -0.1 0.2 0.4  0.2 -0.3 0.1  0 0.1 -0.3  0.1 0.2 0.3"/>
  <UniformMass vertexMass="1"/>
  <TriangularBendingSprings stiffness="300" damping="5"/>
</Node>)",
                     true));  // the compressed spring makes the matrix indefinite: a warning
  ASSERT_TRUE(s.scene().step());
  // SOFA (runSofa, same scene, SparseLDLSolver): the velocities after the step.
  // clang-format off
  const double sofa[18] = {0, 0, 0, 0.744339, -0.799656, -0.351232, -0.0578251, 0.174702,
                           0.401811, -0.437149, 0.514608, 0.240337, -0.0421749, 0.125298,
                           -0.301811, 0.29281, 0.285047, 0.310894};
  // clang-format on
  const auto v = numbers(s.text("@dofs.velocity"));
  ASSERT_EQ(v.size(), 18u);
  for (int i = 0; i < 18; ++i) EXPECT_NEAR(v[i], sofa[i], 5e-6 * std::abs(sofa[i]) + 1e-9) << i;
}

TEST(TriangularBendingSprings, FlatSheetIsAtRest) {
  const Sheet sheet = makeSheet(4, 1.0);
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node name="root" gravity="0 0 0">
  <MeshTopology triangles=")" +
                     sheet.triangles + R"("/>
  <MechanicalObject name="dofs" position=")" +
                     sheet.positions + R"("/>
  <TriangularBendingSprings name="bending" stiffness="1000" damping="3"/>
</Node>)"));
  // 3 x 3 cells: 24 grid segments and 9 diagonals, 12 of them on the border: 21 inside.
  EXPECT_EQ(numbers(s.text("@bending.spring")).size(), 21u * 5);
  ForceFieldChecker check(s.scene(), s.root());
  EXPECT_EQ(check.force().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(check.energy(), 0.0);
}

TEST(TriangularBendingSprings, PassesTheForceFieldTest) {
  const Sheet sheet = makeSheet(3, 2.0);
  checkForceField(R"(<Node name="root" gravity="0 0 0">
  <MeshTopology triangles=")" +
                      sheet.triangles + R"("/>
  <MechanicalObject name="dofs" position=")" +
                      sheet.positions + R"("/>
  <TriangularBendingSprings name="bending" stiffness="500" damping="2"/>
</Node>)",
                  {.rotationInvariant = true});
}

// A square cloth in the plane z = 0, pinned at two corners of one side, hanging under gravity
// -z: stretch springs on the edges, bending springs across them. `position`: where it starts
// (default: flat, its rest shape).
std::string clothScene(const std::string& solvers, const std::string& position = {}) {
  const Sheet sheet = makeSheet(6, 1.0);
  return R"(<Node name="root" gravity="0 0 -9.81" dt="0.02">
  )" + solvers +
         R"(
  <MeshTopology triangles=")" +
         sheet.triangles + R"("/>
  <MechanicalObject name="dofs" rest_position=")" +
         sheet.positions + R"(" position=")" + (position.empty() ? sheet.positions : position) +
         R"("/>
  <UniformMass totalMass="0.5"/>
  <FixedProjectiveConstraint indices="0 5"/>
  <MeshSpringForceField name="stretch" stiffness="200"/>
  <TriangularBendingSprings name="bending" stiffness="2" damping="0"/>
</Node>)";
}
const char* kDamped = R"(<EulerImplicitSolver rayleighMass="2" rayleighStiffness="0.02"/>
  <SparseLDLSolver/>)";
constexpr int kDampedSteps = 250;
constexpr double kWeight = 0.5 * 9.81;

TEST(TriangularBendingSprings, HangingClothLosesEnergyMonotonicallyUnderDamping) {
  SceneHolder s;
  ASSERT_TRUE(s.load(clothScene(kDamped)));
  ForceFieldChecker check(s.scene(), s.root());
  const double first = check.energy() + check.mop().kineticEnergy();
  double previous = first;
  for (int step = 0; step < kDampedSteps; ++step) {
    ASSERT_TRUE(s.scene().step());
    const double e = check.energy() + check.mop().kineticEnergy();
    EXPECT_LE(e, previous + 1e-12 * std::abs(first)) << "step " << step;
    previous = e;
  }
  EXPECT_LT(previous, first - 0.5);  // it fell about half its size (m g dz = 4.9 J per m)
  EXPECT_LT(check.mop().kineticEnergy(), 1e-6 * (first - previous));  // and came to rest
}

TEST(TriangularBendingSprings, HangingClothIsStationaryAndTheForceIsMinusTheEnergyGradient) {
  // Damped to near rest, then Newton from there to the static equilibrium (from the flat sheet
  // Newton fails: flat, the sheet has no stiffness across its plane).
  std::string hanging;
  {
    SceneHolder s;
    ASSERT_TRUE(s.load(clothScene(kDamped)));
    for (int step = 0; step < kDampedSteps; ++step) ASSERT_TRUE(s.scene().step());
    hanging = s.text("@dofs.position");
  }
  SceneHolder s;
  ASSERT_TRUE(s.load(clothScene(R"(<StaticSolver newton_iterations="20"
      absolute_correction_tolerance_threshold="1e-14" relative_correction_tolerance_threshold="0"
      absolute_residual_tolerance_threshold="1e-12" relative_residual_tolerance_threshold="0"/>
  <SparseLDLSolver/>)",
                                hanging),
                     true));
  ASSERT_TRUE(s.scene().step());
  ForceFieldChecker check(s.scene(), s.root());
  // It hangs: the free corners fell; the bending springs work.
  const auto x = numbers(s.text("@dofs.position"));
  EXPECT_LT(x[3 * 35 + 2], -0.3);
  // Total force (gravity + springs) = -grad(energy), everywhere (pinned points included).
  const Eigen::VectorXd f = check.force();
  const Eigen::VectorXd fd = check.finiteDifferenceForce(1e-6);
  EXPECT_LT((f - fd).cwiseAbs().maxCoeff(), 1e-6 * kWeight);
  // Stationary: the gradient vanishes on the free points (the two pinned ones hold the cloth).
  double residual = 0, pinned = 0;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    double& worst = (i / 3 == 0 || i / 3 == 5) ? pinned : residual;
    worst = std::max(worst, std::abs(f[i]));
  }
  EXPECT_LT(residual, 1e-9 * kWeight);
  EXPECT_GT(pinned, 0.1 * kWeight);
  // A minimum: moving a free point either way raises the energy.
  const double e0 = check.energy();
  for (Eigen::Index j : {3 * 35 + 2, 3 * 14 + 0, 3 * 20 + 1})
    for (double h : {1e-3, -1e-3}) {
      check.shift(j, h);
      EXPECT_GT(check.energy(), e0) << j;
      check.shift(j, -h);
    }
}

TEST(TriangularBendingSprings, WarmStepAllocatesNothing) {
  SceneHolder s;
  ASSERT_TRUE(s.load(clothScene("<EulerImplicitSolver/><SparseLDLSolver/>")));
  ASSERT_TRUE(s.step(2));
  auto* field = s.get<BaseForceField>("@bending");
  ASSERT_NE(field, nullptr);
  MechanicalParams mp;
  StateOffsets offsets;
  offsets.set(field->states()[0], 0);
  AssembledMatrix matrix;
  for (int pass = 0; pass < 2; ++pass) {  // the first pass records the pattern
    matrix.begin(3 * 36);
    g_allocations = 0;
    g_counting = pass == 1;
    field->accumulateForce(mp, VecId::force());
    field->accumulateDForce(mp, VecId::force(), VecId::velocity());
    field->accumulateKMatrix(mp, matrix, offsets);
    g_counting = false;
  }
  EXPECT_EQ(g_allocations, 0);
}

TEST(TriangularBendingSprings, BadInputIsReported) {
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<TriangularBendingSprings/></Node>)",
                            {"needs a topology"})
                  .field,
              "topology");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(R"(<Node><MeshTopology edges="0 1"/>
<MechanicalObject position="0 0 0  1 0 0"/><TriangularBendingSprings/></Node>)",
                            {"has no triangles"})
                  .field,
              "topology");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(R"(<Node><MeshTopology triangles="0 1 2  0 2 7"/>
<MechanicalObject position="0 0 0  1 -1 0  2 0 0  1 1 0"/><TriangularBendingSprings/></Node>)",
                            {"out of range"})
                  .field,
              "topology");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(R"(<Node><MeshTopology triangles="0 1 2  0 2 3"/>
<MechanicalObject position="0 0 0  1 -1 0  2 0 0  1 1 0"/>
<TriangularBendingSprings stiffness="-5"/></Node>)",
                            {})
                  .field,
              "stiffness");
  }
}

}  // namespace
}  // namespace stroma::test
