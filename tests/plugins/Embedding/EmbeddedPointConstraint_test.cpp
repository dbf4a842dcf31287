// SPDX-License-Identifier: MIT
// EmbeddedPointConstraint: points of a surface embedded in a grid (BarycentricMapping, trilinear)
// fixed or moved through the pseudo-inverse of the interpolation (seed 001, chapter 3 section
// 4.1). Forces mapped through J^T conserve power (section 4.2); embedded fixed points stay
// fixed under gravity with implicit Euler + CG and with the static solver; an imposed
// displacement or movement is reached exactly; on grid nodes the constraint is the fixing of
// those nodes; dependent points (singular H H^T) are reported and handled in least squares; bad
// input is reported.
#include <gtest/gtest.h>

#include <random>

#include "core/StateTypes.h"
#include "plugins/MeshIO/SceneFixture.h"
#include "simulation/Mapping.h"
#include "simulation/MechanicalState.h"

namespace stroma::test {
namespace {

using PointMapping = Mapping<Vec3Types, Vec3Types>;

// Surface points in the grid [0, 2] x [0, 1] x [0, 1]: the first three inside cells next to
// x = 0 (not on nodes), the others spread along the beam.
const char* kSurface =
    "0.1 0.2 0.3  0.15 0.8 0.7  0.3 0.5 0.45  1 0.5 0.5  1.7 0.2 0.9  1.95 0.95 0.05  "
    "0.1 0.2 0.3";

// A grid body (5 x 3 x 3 points, corotational hexahedra, 2 kg) with an embedded surface; `solver`
// and `constraint` go into the grid's node.
std::string bodyScene(const std::string& solver, const std::string& constraint,
                      const std::string& surface = kSurface, const char* method = "large") {
  return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
  <Node name="Body">
    )" + solver +
         R"(
    <RegularGridTopology name="grid" n="5 3 3" min="0 0 0" max="2 1 1"/>
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="2"/>
    <HexahedronFEMForceField method=")" +
         method + R"(" youngModulus="5000" poissonRatio="0.3"/>
    )" + constraint +
         R"(
    <Node name="Surface">
      <MechanicalObject name="points" position=")" +
         surface + R"("/>
      <BarycentricMapping name="mapping"/>
    </Node>
  </Node>
</Node>)";
}

const char* kImplicit = R"(<EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.1"/>
    <CGLinearSolver iterations="1000" tolerance="1e-12" threshold="1e-40"/>)";
const char* kStatic = R"(<StaticSolver newton_iterations="1"/>
    <CGLinearSolver iterations="1000" tolerance="1e-12" threshold="1e-40"/>)";

class EmbeddedPointConstraintTest : public SceneFixture {
 protected:
  MechanicalState<Vec3Types>* grid() {
    return dynamic_cast<MechanicalState<Vec3Types>*>(object("/Body/dofs"));
  }
  PointMapping* mapping() { return dynamic_cast<PointMapping*>(object("/Body/Surface/mapping")); }
  /// Where the grid puts embedded point i: J x (the interpolation; exact for trilinear weights).
  Vec3d embedded(std::size_t i) {
    const Eigen::SparseMatrix<double, Eigen::RowMajor> J = mapping()->jacobian();
    const auto& x = grid()->readCoord(VecId::position());
    Vec3d p = Vec3d::Zero();
    for (int d = 0; d < 3; ++d)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(J, 3 * i + d); e; ++e)
        p[d] += e.value() * x[e.col() / 3][e.col() % 3];
    return p;
  }
  std::vector<Vec3d> surface() {
    std::vector<Vec3d> points;
    std::istringstream in(kSurface);
    for (double x, y, z; in >> x >> y >> z;) points.emplace_back(x, y, z);
    return points;
  }
};

TEST_F(EmbeddedPointConstraintTest, MappedForcesConservePowerOnASparseGrid) {
  // A box surface in a SparseGridTopology (boundary cells), points on and inside it mapped.
  ASSERT_TRUE(load(R"(<Node name="root" gravity="0 0 0">
  <Node name="Body">
    <SparseGridTopology name="grid" n="6 4 4"
        position="0 -0.05 -0.05  0.4 -0.05 -0.05  0 0.05 -0.05  0.4 0.05 -0.05
                  0 -0.05 0.05   0.4 -0.05 0.05   0 0.05 0.05   0.4 0.05 0.05"
        triangles="0 2 3  0 3 1  4 5 7  4 7 6  0 1 5  0 5 4  2 6 7  2 7 3  0 4 6  0 6 2
                   1 3 7  1 7 5"/>
    <MechanicalObject name="dofs"/>
    <Node name="Surface">
      <MechanicalObject name="points" position="0 -0.05 -0.05  0.4 0.05 0.05  0.13 0.01 -0.02
          0.31 -0.04 0.049  0.2 0 0  0.05 0.05 0.0  0.39 -0.01 0.03"/>
      <BarycentricMapping name="mapping"/>
    </Node>
  </Node>
</Node>)"))
      << messages();
  auto* map = mapping();
  ASSERT_NE(map, nullptr);
  const std::size_t n = map->input()->size(), m = map->output()->size();
  ASSERT_GT(n, 8u);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Vec3d> vp(n), fp(n, Vec3d::Zero()), vq(m), fq(m);
    for (Vec3d& v : vp) v = Vec3d(uniform(random), uniform(random), uniform(random));
    for (Vec3d& f : fq) f = Vec3d(uniform(random), uniform(random), uniform(random));
    map->applyJ(vq, vp);   // v_q = J v_p
    map->applyJT(fp, fq);  // f_p = J^T f_q
    double gridPower = 0, surfacePower = 0, scale = 0;
    for (std::size_t i = 0; i < n; ++i) {
      gridPower += fp[i].dot(vp[i]);
      scale += fp[i].norm() * vp[i].norm();
    }
    for (std::size_t i = 0; i < m; ++i) surfacePower += fq[i].dot(vq[i]);
    EXPECT_NEAR(gridPower, surfacePower, 1e-14 * scale) << trial;
  }
}

TEST_F(EmbeddedPointConstraintTest, FixedPointsStayFixedUnderGravityImplicitAndStatic) {
  for (const char* solver : {kImplicit, kStatic}) {
    scene.unload();
    ASSERT_TRUE(load(bodyScene(
        solver,
        R"(<EmbeddedPointConstraint name="pin" indices="0 1 2" mapping="@Surface/mapping"/>)",
        kSurface, solver == kStatic ? "small" : "large")))
        << messages();
    const auto p0 = surface();
    double worst = 0, sag = 0, drift = 0;
    std::vector<Vec3d> first;
    for (int step = 0; step < 20; ++step) {
      ASSERT_TRUE(scene.step()) << messages();
      for (std::size_t i = 0; i < 3; ++i) worst = std::max(worst, (embedded(i) - p0[i]).norm());
      sag = std::max(sag, p0[4].y() - embedded(4).y());
      const auto& x = grid()->readCoord(VecId::position());
      if (step == 0) first = x;
      for (std::size_t i = 0; i < x.size(); ++i) drift = std::max(drift, (x[i] - first[i]).norm());
    }
    {
      std::ostringstream text;
      text << std::scientific << worst;
      RecordProperty(solver == kStatic ? "staticWorst" : "implicitWorst", text.str());
    }
    EXPECT_LT(worst, 1e-10) << solver;
    // The static solution is the constrained equilibrium itself (the projector acts inside the
    // solve, not only on the result): the next steps do not move it.
    if (solver == kStatic) {
      EXPECT_LT(drift, 1e-9 * sag);
    }
    EXPECT_GT(sag, 1e-3) << solver;  // the free end fell
    EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  }
}

TEST_F(EmbeddedPointConstraintTest, AnImposedMovementIsReachedExactly) {
  ASSERT_TRUE(load(bodyScene(kImplicit, R"(<EmbeddedPointConstraint name="pull" indices="0 1 2"
        keyTimes="0 0.1 1" movements="0 0 0  0 0.05 0.02  0 0.05 0.02"/>)",
                             "0.1 0.2 0.3  0.15 0.8 0.7  0.3 0.5 0.45  1 0.5 0.5")))
      << messages();
  const auto p0 = surface();
  double worst = 0;
  for (int step = 1; step <= 20; ++step) {
    ASSERT_TRUE(scene.step()) << messages();
    const double t = 0.01 * step, s = std::min(t / 0.1, 1.0);
    const Vec3d shift(0, 0.05 * s, 0.02 * s);
    for (std::size_t i = 0; i < 3; ++i)
      worst = std::max(worst, (embedded(i) - (p0[i] + shift)).norm());
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
}

TEST_F(EmbeddedPointConstraintTest, AConstantDisplacementIsReachedByTheStaticSolver) {
  ASSERT_TRUE(load(bodyScene(kStatic, R"(<EmbeddedPointConstraint indices="0 1 2 3"
        displacement="0.02 -0.01 0.03"/>)",
                             "0.1 0.2 0.3  0.15 0.8 0.7  0.3 0.5 0.45  1.9 0.5 0.5", "small")))
      << messages();
  ASSERT_TRUE(scene.step()) << messages();
  const auto p0 = surface();
  const std::vector<Vec3d> rest{
      {0.1, 0.2, 0.3}, {0.15, 0.8, 0.7}, {0.3, 0.5, 0.45}, {1.9, 0.5, 0.5}};
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_LT((embedded(i) - (rest[i] + Vec3d(0.02, -0.01, 0.03))).norm(), 1e-10) << i;
}

TEST_F(EmbeddedPointConstraintTest, OnGridNodesItIsTheFixingOfTheNodes) {
  // The 9 points of the face x = 0 of the 5 x 3 x 3 grid (indices 0, 5, ..., 40).
  std::string onNodes, nodes, all;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      onNodes += "0 " + std::to_string(0.5 * j) + " " + std::to_string(0.5 * k) + "  ";
      nodes += std::to_string(5 * (j + 3 * k)) + " ";
    }
  const std::string points = onNodes + "1.3 0.4 0.6";
  std::vector<Vec3d> embeddedRun, fixedRun;
  ASSERT_TRUE(load(
      bodyScene(kImplicit, R"(<EmbeddedPointConstraint indices="0 1 2 3 4 5 6 7 8"/>)", points)))
      << messages();
  for (int step = 0; step < 20; ++step) ASSERT_TRUE(scene.step()) << messages();
  embeddedRun = grid()->readCoord(VecId::position());
  scene.unload();
  ASSERT_TRUE(
      load(bodyScene(kImplicit, "<FixedProjectiveConstraint indices=\"" + nodes + "\"/>", points)))
      << messages();
  for (int step = 0; step < 20; ++step) ASSERT_TRUE(scene.step()) << messages();
  fixedRun = grid()->readCoord(VecId::position());
  ASSERT_EQ(embeddedRun.size(), fixedRun.size());
  double worst = 0, moved = 0;
  for (std::size_t i = 0; i < fixedRun.size(); ++i) {
    worst = std::max(worst, (embeddedRun[i] - fixedRun[i]).norm());
    moved = std::max(moved, (fixedRun[i] - grid()->readCoord(VecId::restPosition())[i]).norm());
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(moved, 1e-3);
}

TEST_F(EmbeddedPointConstraintTest, DependentPointsAreReportedAndImposedInLeastSquares) {
  // Point 6 is point 0 again: H H^T is singular.
  ASSERT_TRUE(load(bodyScene(kImplicit, R"(<EmbeddedPointConstraint indices="0 1 2 6"/>)")))
      << messages();
  EXPECT_NE(messages().find("1 of the 4 constrained points depend on the others"),
            std::string::npos)
      << messages();
  const auto p0 = surface();
  double worst = 0;
  for (int step = 0; step < 10; ++step) {
    ASSERT_TRUE(scene.step()) << messages();
    for (std::size_t i : {0, 1, 2, 6}) worst = std::max(worst, (embedded(i) - p0[i]).norm());
  }
  EXPECT_LT(worst, 1e-10);
}

TEST_F(EmbeddedPointConstraintTest, ReportsBadInput) {
  EXPECT_FALSE(load(bodyScene(kImplicit, R"(<EmbeddedPointConstraint indices="0 99"/>)")));
  EXPECT_NE(messages().find("index 99 is out of range of the 7 points"), std::string::npos)
      << messages();
  scene.unload();
  EXPECT_FALSE(load(R"(<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
  <EmbeddedPointConstraint indices="0"/>
</Node>)"));
  EXPECT_NE(messages().find("no mapping from /root/dofs in the child nodes"), std::string::npos)
      << messages();
  scene.unload();
  EXPECT_FALSE(load(bodyScene(kImplicit, R"(<EmbeddedPointConstraint indices="0"
      keyTimes="0 1" movements="0 0 0"/>)")));
  EXPECT_NE(messages().find("has 1 movements for 2 key times"), std::string::npos) << messages();
  scene.unload();
  ASSERT_TRUE(load(bodyScene(R"(<EulerImplicitSolver/><SparseLDLSolver/>)",
                             R"(<EmbeddedPointConstraint indices="0"/>)")))
      << messages();
  ASSERT_TRUE(scene.step()) << messages();
  EXPECT_NE(messages().find("cannot hold the projection"), std::string::npos) << messages();
}

}  // namespace
}  // namespace stroma::test
