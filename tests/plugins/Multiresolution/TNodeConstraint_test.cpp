// SPDX-License-Identifier: MIT
// TNodeConstraint with CGLinearSolver, seed 001 figure 4.16: a beam in traction with Poisson's
// ratio 0, meshed coarse, fine, and mixed with T-nodes, reaches the same equilibrium, the exact
// one u_x = t x / E (linear: every mesh of trilinear hexahedra holds it), at the points the meshes
// share; without the T-node handling the mixed mesh is not conforming and its answer is wrong.
// Under gravity, with implicit Euler and CG, the T-nodes stay at the interpolation of their
// parents. An assembled solve is reported.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "MultiresolutionGrid.h"
#include "core/StateTypes.h"
#include "plugins/MeshIO/SceneFixture.h"
#include "simulation/MechanicalState.h"

namespace stroma::test {
namespace {

// The beam [0, 4] x [0, 1] x [0, 1], 4 coarse cells along x; traction t on the face x = 4.
constexpr double kLength = 4, kYoung = 1000, kTraction = 10;

struct BeamMesh {
  multiresolution::MixedGrid grid;
  std::string fixed, loaded, forces;
};

// The mesh the topology component makes (same kernel), the points fixed at x = 0, and the
// consistent nodal forces of the uniform traction: a quarter of each end face's area per node.
// 4 coarse cells along x, and 1 x 1 (4 flags) or 2 x 2 (16 flags) across.
int cellsAcross(const std::vector<char>& refined) { return refined.size() == 4 ? 1 : 2; }

BeamMesh beamMesh(const std::vector<char>& refined) {
  BeamMesh m;
  const int across = cellsAcross(refined) + 1;
  m.grid = multiresolution::makeMixedGrid({5, across, across}, Vec3d::Zero(), Vec3d(kLength, 1, 1),
                                          refined);
  const auto& p = m.grid.points;
  std::vector<Vec3d> force(p.size(), Vec3d::Zero());
  for (const Hexahedron& h : m.grid.hexahedra) {
    // Vertices 1 2 6 5 form the face of largest x.
    if (std::abs(p[h[1]].x() - kLength) > 1e-12) continue;
    const double area = (p[h[2]] - p[h[1]]).norm() * (p[h[5]] - p[h[1]]).norm();
    for (int v : {1, 2, 6, 5}) force[h[v]].x() += kTraction * area / 4;
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i].x() == 0) m.fixed += std::to_string(i) + " ";
    if (force[i].x() != 0) {
      m.loaded += std::to_string(i) + " ";
      std::ostringstream f;
      f.precision(17);
      f << force[i].x() << " 0 0  ";
      m.forces += f.str();
    }
  }
  return m;
}

std::string refineCells(const std::vector<char>& refined) {
  std::string cells;
  for (std::size_t c = 0; c < refined.size(); ++c)
    if (refined[c]) cells += std::to_string(c) + " ";
  return cells;
}

std::string beamScene(
    const std::vector<char>& refined, bool handleTNodes,
    const std::string& linearSolver =
        R"(<CGLinearSolver iterations="3000" tolerance="1e-13" threshold="1e-40"/>)") {
  const BeamMesh m = beamMesh(refined);
  return R"(<Node name="root" gravity="0 0 0" dt="1">
  <StaticSolver newton_iterations="1" maxNbIterationsLineSearch="1"/>
  )" + linearSolver +
         R"(
  <MultiresolutionGridTopology name="grid" n="5 )" +
         std::to_string(cellsAcross(refined) + 1) + " " + std::to_string(cellsAcross(refined) + 1) +
         R"(" min="0 0 0" max="4 1 1" refineCells=")" + refineCells(refined) + R"("/>
  <MechanicalObject name="dofs"/>
  )" + (handleTNodes ? "<TNodeConstraint name=\"tNodes\"/>" : "") +
         R"(
  <HexahedronFEMForceField method="small" youngModulus="1000" poissonRatio="0"/>
  <FixedProjectiveConstraint indices=")" +
         m.fixed + R"("/>
  <ConstantForceField indices=")" +
         m.loaded + R"(" forces=")" + m.forces + R"("/>
</Node>)";
}

class TNodeConstraintTest : public SceneFixture {
 protected:
  const std::vector<Vec3d>& positions() {
    auto* state = dynamic_cast<MechanicalState<Vec3Types>*>(object("/dofs"));
    EXPECT_NE(state, nullptr);
    return state->readCoord(VecId::position());
  }
  /// Largest distance from the exact equilibrium x + t x / E e_x over the coarse nodes (integer
  /// coordinates: the points all three meshes share), and over all nodes.
  std::pair<double, double> errors() {
    double shared = 0, all = 0;
    const auto& x = positions();
    const auto& rest = grid.points;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3d exact = rest[i] + Vec3d(kTraction * rest[i].x() / kYoung, 0, 0);
      const double e = (x[i] - exact).norm();
      all = std::max(all, e);
      if ((rest[i] - rest[i].array().round().matrix()).norm() == 0) shared = std::max(shared, e);
    }
    return {shared, all};
  }
  multiresolution::MixedGrid grid;
};

std::string scientific(double value) {
  std::ostringstream text;
  text.precision(3);
  text << std::scientific << value;
  return text.str();
}

const std::vector<char> kCoarse{0, 0, 0, 0}, kFine{1, 1, 1, 1}, kMixed{0, 1, 1, 0};

TEST_F(TNodeConstraintTest, BeamInTractionHasTheSameEquilibriumCoarseFineAndMixed) {
  // The end displacement is t L / E = 0.04; the solver tolerance gives ~1e-12.
  for (const auto* refined : {&kCoarse, &kFine, &kMixed}) {
    scene.unload();
    grid = beamMesh(*refined).grid;
    ASSERT_TRUE(load(beamScene(*refined, true))) << messages();
    ASSERT_TRUE(scene.step()) << messages();
    EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
    const auto [shared, all] = errors();
    RecordProperty("error" + std::to_string(refined == &kCoarse ? 0
                                            : refined == &kFine ? 1
                                                                : 2),
                   scientific(all));
    EXPECT_LT(shared, 1e-10) << refineCells(*refined);
    EXPECT_LT(all, 1e-10) << refineCells(*refined);
  }
  EXPECT_EQ(grid.tNodes.size(), 10u);  // the mixed beam: 5 on each of its two interfaces
}

TEST_F(TNodeConstraintTest, ACheckerboardOfRefinedCellsHoldsTheExactTraction) {
  // 4 x 2 x 2 cells, every other one refined: T-nodes on faces and edges of every orientation,
  // on the clamped and the loaded ends too (their nodal forces go to their parents).
  std::vector<char> checkerboard(16);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i) checkerboard[i + 4 * (j + 2 * k)] = (i + j + k) % 2;
  grid = beamMesh(checkerboard).grid;
  ASSERT_TRUE(load(beamScene(checkerboard, true))) << messages();
  ASSERT_TRUE(scene.step()) << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  const auto [shared, all] = errors();
  RecordProperty("checkerboardError", scientific(all));
  RecordProperty("checkerboardTNodes", std::to_string(grid.tNodes.size()));
  EXPECT_GT(grid.tNodes.size(), 20u);
  EXPECT_LT(all, 1e-10);
}

TEST_F(TNodeConstraintTest, WithoutTheTNodeHandlingTheMixedBeamIsWrong) {
  grid = beamMesh(kMixed).grid;
  ASSERT_TRUE(load(beamScene(kMixed, false))) << messages();
  ASSERT_TRUE(scene.step()) << messages();
  const auto [shared, all] = errors();
  RecordProperty("errorAtSharedNodes", scientific(shared));
  RecordProperty("errorAtAllNodes", scientific(all));
  // The fine side's T-nodes are pulled off the coarse faces: the mesh opens at the interfaces.
  EXPECT_GT(all, 1e-3) << "the error was " << all;
  EXPECT_GT(shared, 1e-4) << "the error was " << shared;
}

TEST_F(TNodeConstraintTest, TNodesStayInterpolatedUnderGravityWithImplicitEuler) {
  grid = beamMesh(kMixed).grid;
  ASSERT_TRUE(load(R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
  <EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.1"/>
  <CGLinearSolver iterations="1000" tolerance="1e-10" threshold="1e-40"/>
  <MultiresolutionGridTopology name="grid" n="5 2 2" min="0 0 0" max="4 1 1" refineCells="1 2"/>
  <MechanicalObject name="dofs"/>
  <TNodeConstraint name="tNodes"/>
  <UniformMass totalMass="4"/>
  <HexahedronFEMForceField method="large" youngModulus="1000" poissonRatio="0.3"/>
  <FixedProjectiveConstraint indices="0 1 2 3"/>
</Node>)"))
      << messages();
  double sag = 0;
  for (int step = 0; step < 30; ++step) {
    ASSERT_TRUE(scene.step()) << messages();
    const auto& x = positions();
    double worst = 0;
    for (const auto& t : grid.tNodes) {
      Vec3d interpolated = Vec3d::Zero();
      for (int k = 0; k < t.parentCount; ++k) interpolated += t.weights[k] * x[t.parents[k]];
      worst = std::max(worst, (x[t.node] - interpolated).norm());
    }
    EXPECT_LT(worst, 1e-13) << "step " << step;
    sag = std::max(sag, -(x.back().y() - grid.points.back().y()));
  }
  EXPECT_GT(sag, 1e-3);  // it moved
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
}

TEST_F(TNodeConstraintTest, TNodesStayInterpolatedWithExplicitEuler) {
  // The explicit path: forces pushed to the parents by the projection, T-node positions and
  // velocities interpolated at the end of each step.
  grid = beamMesh(kMixed).grid;
  ASSERT_TRUE(load(R"(<Node name="root" gravity="0 -9.81 0" dt="0.0005">
  <EulerExplicitSolver/>
  <MultiresolutionGridTopology name="grid" n="5 2 2" min="0 0 0" max="4 1 1" refineCells="1 2"/>
  <MechanicalObject name="dofs"/>
  <TNodeConstraint name="tNodes"/>
  <UniformMass totalMass="4"/>
  <HexahedronFEMForceField method="large" youngModulus="1000" poissonRatio="0.3"/>
  <FixedProjectiveConstraint indices="0 1 2 3"/>
</Node>)"))
      << messages();
  double worst = 0;
  for (int step = 0; step < 200; ++step) {
    ASSERT_TRUE(scene.step()) << messages();
    const auto& x = positions();
    for (const auto& t : grid.tNodes) {
      Vec3d interpolated = Vec3d::Zero();
      for (int k = 0; k < t.parentCount; ++k) interpolated += t.weights[k] * x[t.parents[k]];
      worst = std::max(worst, (x[t.node] - interpolated).norm());
    }
  }
  EXPECT_LT(worst, 1e-13);
  EXPECT_GT(grid.points.back().y() - positions().back().y(), 1e-3);  // it fell
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
}

TEST_F(TNodeConstraintTest, AnAssembledSolveIsReported) {
  grid = beamMesh(kMixed).grid;
  ASSERT_TRUE(load(beamScene(kMixed, true, R"(<SparseLDLSolver/>)"))) << messages();
  ASSERT_TRUE(scene.step()) << messages();
  EXPECT_NE(messages().find("cannot hold the interpolation of the 10 T-nodes"), std::string::npos)
      << messages();
}

TEST_F(TNodeConstraintTest, ReportsAMissingGridAndAWrongOrder) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
  <TNodeConstraint/>
</Node>)"));
  EXPECT_NE(messages().find("no MultiresolutionGridTopology in /root"), std::string::npos)
      << messages();
  scene.unload();
  ASSERT_TRUE(load(R"(<Node name="root">
  <MultiresolutionGridTopology n="3 2 2" max="2 1 1" refineCells="1"/>
  <MechanicalObject name="dofs"/>
  <FixedProjectiveConstraint name="clamp" indices="0"/>
  <TNodeConstraint/>
</Node>)"))
      << messages();
  EXPECT_NE(messages().find("clamp comes before it"), std::string::npos) << messages();
  scene.unload();
  EXPECT_FALSE(load(R"(<Node name="root">
  <MultiresolutionGridTopology n="1 2 2"/>
</Node>)"));
  EXPECT_NE(messages().find("field 'n': value 1 is outside the allowed range"), std::string::npos)
      << messages();
}

}  // namespace
}  // namespace stroma::test
