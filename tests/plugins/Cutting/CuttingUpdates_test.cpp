// SPDX-License-Identifier: MIT
// The components that follow removed tetrahedra incrementally (TopologyChange.h) hold, after
// the removals, what a rebuild from scratch on the new mesh gives (to round-off): lumped and
// consistent masses, barycentric mappings, the boundary surface of
// Tetra2TriangleTopologicalMapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/Mapping.h"
#include "topology/MeshAdjacency.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

// Removals over three steps (no solver: the points stay where the masses were computed).
const char* kRemovals = R"(times="0 0.01 0.02" tetrahedra="0 5 17 40 41, 3 60 61 62 63, 7")";

/// A 0.4 x 0.1 x 0.1 block in 96 tetrahedra; TETRAHEDRA is "" (the grid's, then cut) or a
/// list; MASS the mass component; CUT the remover's attributes (or nothing).
std::string block(const std::string& tetrahedra, const std::string& mass, bool cut) {
  std::string topology =
      tetrahedra.empty()
          ? R"(<TetrahedronSetTopologyContainer name="topology"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topology"/>)"
          : R"(<TetrahedronSetTopologyContainer name="topology" position="@grid.position" tetrahedra=")" +
                tetrahedra + R"("/>)";
  return R"(
<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <Node name="Block">
    <RegularGridTopology name="grid" min="0 -0.05 -0.05" max="0.4 0.05 0.05" n="5 3 3"/>
    <MechanicalObject name="dofs" template="Vec3" position="@grid.position"/>
    )" + topology +
         R"(
    <)" + mass +
         R"(/>
    )" + (cut ? std::string("<TetrahedraRemover ") + kRemovals + "/>" : std::string()) +
         R"(
    <Node name="Embedded">
      <MechanicalObject name="points" template="Vec3"
          position="0.02 -0.04 -0.03  0.08 -0.01 -0.045  0.25 -0.03 -0.01  0.22 0.02 -0.04
                    0.28 0.04 -0.02  0.03 -0.02 -0.04  0.26 -0.01 0.02  0.09 -0.045 -0.045
                    0.45 0 0  0.15 0.02 -0.03"/>
      <BarycentricMapping name="mapping" input="@../dofs" output="@points"
                          input_topology="@../topology"/>
    </Node>
    <Node name="Surface">
      <TriangleSetTopologyContainer name="surface"/>
      <Tetra2TriangleTopologicalMapping input="@../topology" output="@surface"/>
    </Node>
  </Node>
</Node>)";
}

/// The cut block after the removals, and the same mesh built from scratch.
struct CutAndRebuilt {
  SceneHolder cut, rebuilt;
  void load(const std::string& mass) {
    // The barycentric mapping warns once about the points it re-attached.
    ASSERT_TRUE(cut.load(block("", mass, true), true));
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(cut.scene().step());
    ASSERT_EQ(cut.get<Topology>("@Block/topology")->tetrahedra().size(), 96u - 11u);
    ASSERT_TRUE(rebuilt.load(block(cut.text("@Block/topology.tetrahedra"), mass, false), true));
  }
};

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

/// The mass matrix and the gravity force of the block's node.
void expectSameMass(SceneHolder& cut, SceneHolder& rebuilt) {
  ForceFieldChecker a(cut.scene(), *cut.root().findChild("Block"));
  ForceFieldChecker b(rebuilt.scene(), *rebuilt.root().findChild("Block"));
  const Eigen::VectorXd fa = a.force(), fb = b.force();
  EXPECT_LT((fa - fb).cwiseAbs().maxCoeff(), 1e-13 * fb.cwiseAbs().maxCoeff());
  EXPECT_LT(relativeDifference(a.assembled(1, 0, 0), b.assembled(1, 0, 0)), 1e-13);
  EXPECT_LT(relativeDifference(a.matrixFreeMass(), b.matrixFreeMass()), 1e-13);
}

TEST(CuttingUpdates, DiagonalMassEqualsARebuild) {
  CutAndRebuilt s;
  s.load(R"(DiagonalMass name="mass" massDensity="1000")");
  expectSameMass(s.cut, s.rebuilt);
}

TEST(CuttingUpdates, DiagonalMassWithATotalMassEqualsARebuild) {
  CutAndRebuilt s;
  s.load(R"(DiagonalMass name="mass" totalMass="3")");
  expectSameMass(s.cut, s.rebuilt);
}

TEST(CuttingUpdates, ConsistentMeshMatrixMassEqualsARebuild) {
  CutAndRebuilt s;
  s.load(R"(MeshMatrixMass name="mass" massDensity="1000")");
  expectSameMass(s.cut, s.rebuilt);
}

TEST(CuttingUpdates, LumpedMeshMatrixMassEqualsARebuild) {
  CutAndRebuilt s;
  s.load(R"(MeshMatrixMass name="mass" massDensity="1000" lumping="1")");
  expectSameMass(s.cut, s.rebuilt);
}

TEST(CuttingUpdates, BarycentricMappingEqualsARebuild) {
  CutAndRebuilt s;
  s.load(R"(DiagonalMass name="mass" massDensity="1000")");
  using Map = Mapping<Vec3Types, Vec3Types>;
  Map* a = s.cut.get<Map>("@Block/Embedded/mapping");
  Map* b = s.rebuilt.get<Map>("@Block/Embedded/mapping");
  // The same random field of the input points, mapped by both.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3d> in(45);
  for (Vec3d& x : in) x = Vec3d(u(random), u(random), u(random));
  std::vector<Vec3d> outA, outB;
  a->apply(outA, in);
  b->apply(outB, in);
  ASSERT_EQ(outA.size(), 10u);
  for (std::size_t k = 0; k < outA.size(); ++k)
    EXPECT_LT((outA[k] - outB[k]).norm(), 1e-12) << "point " << k;
  // J^T of both.
  std::vector<Vec3d> forces(10, Vec3d(0.3, -1, 2)), backA(45, Vec3d::Zero()),
      backB(45, Vec3d::Zero());
  a->applyJT(backA, forces);
  b->applyJT(backB, forces);
  for (std::size_t i = 0; i < backA.size(); ++i) EXPECT_LT((backA[i] - backB[i]).norm(), 1e-12);
  // One warning, counting the points that lost their tetrahedron (besides the one at init
  // about point 8, outside the block).
  std::size_t warnings = 0;
  for (const Message& m : s.cut.scene().log().messages())
    warnings += m.level == MessageLevel::warning &&
                m.text.find("lost their tetrahedron") != std::string::npos;
  EXPECT_EQ(warnings, 1u);
}

TEST(CuttingUpdates, TetrahedronFEMForceFieldEqualsARebuild) {
  for (const char* method : {"large", "small", "polar"}) {
    SCOPED_TRACE(method);
    CutAndRebuilt s;
    s.load(std::string(R"(DiagonalMass name="mass" massDensity="1000"/>
    <TetrahedronFEMForceField name="FEM" youngModulus="1e4" poissonRatio="0.3" method=")") +
           method + "\"");
    // The same deformed positions in both: forces and stiffness matrices must agree.
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-0.01, 0.01);
    std::vector<double> x = numbers(s.cut.text("@Block/dofs.position"));
    std::string text;
    for (double& v : x) text += std::to_string(v + u(random)) + " ";
    s.cut.set("@Block/dofs.position", text);
    s.rebuilt.set("@Block/dofs.position", text);
    ForceFieldChecker a(s.cut.scene(), *s.cut.root().findChild("Block"));
    ForceFieldChecker b(s.rebuilt.scene(), *s.rebuilt.root().findChild("Block"));
    const Eigen::VectorXd fa = a.force(), fb = b.force();
    EXPECT_LT((fa - fb).cwiseAbs().maxCoeff(), 1e-12 * fb.cwiseAbs().maxCoeff());
    EXPECT_LT(relativeDifference(a.assembled(0, 0, 1), b.assembled(0, 0, 1)), 1e-12);
    EXPECT_NEAR(a.energy(), b.energy(), 1e-12 * std::abs(b.energy()));
  }
}

/// Triangles as a set, each rotated to start at its smallest vertex (orientation kept).
std::set<Triangle> orientedSet(const std::vector<Triangle>& triangles) {
  std::set<Triangle> out;
  for (Triangle t : triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}

TEST(CuttingUpdates, VisualSurfaceEqualsARebuild) {
  CutAndRebuilt s;
  s.load(R"(DiagonalMass name="mass" massDensity="1000")");
  const Topology* a = s.cut.get<Topology>("@Block/Surface/surface");
  const Topology* b = s.rebuilt.get<Topology>("@Block/Surface/surface");
  const Topology* tetrahedra = s.cut.get<Topology>("@Block/topology");
  EXPECT_EQ(orientedSet(a->triangles()), orientedSet(b->triangles()));
  EXPECT_EQ(orientedSet(a->triangles()),
            orientedSet(computeBoundaryTriangles(tetrahedra->tetrahedra())));
  EXPECT_EQ(a->triangles().size(), b->triangles().size());
  // Its edges follow.
  EXPECT_EQ(a->edges().size(), b->edges().size());
  // New faces appeared: the boundary is larger than the uncut block's 64 triangles.
  EXPECT_GT(a->triangles().size(), 64u);
}

}  // namespace
}  // namespace stroma::test
