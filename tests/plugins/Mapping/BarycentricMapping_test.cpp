// SPDX-License-Identifier: MIT
// BarycentricMapping: points embedded in tetrahedra (MeshTopology) and in the hexahedra of a
// RegularGridTopology. J is consistent with apply; the weights lie in [0, 1] and sum to 1
// inside; a linear motion of the mesh moves the points exactly (patch test); points outside are
// reported; a falling body carries its embedded surface, and forces on the surface act on the
// body as J^T F; springs between embedded points assemble as J^T K J.
#include "plugins/Mapping/MappingChecks.h"
#include "support/TestSprings.h"

namespace stroma::test {
namespace {

using PointMapping = Mapping<Vec3Types, Vec3Types>;

// A cube [0, 2]^3 of 2 x 2 x 2 cells (27 points, numbered x fastest as RegularGridTopology),
// each cell cut into the 6 tetrahedra around its diagonal (Kuhn's triangulation, conforming).
struct CubeMesh {
  std::string points, tetrahedra, edges;
  std::vector<Vec3d> nodes;
  CubeMesh() {
    auto id = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          nodes.emplace_back(i, j, k);
          points += std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(k) + "  ";
        }
    std::vector<std::array<int, 2>> edgeList;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const int c[8] = {
              id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
              id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
          const int around[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                    {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
          for (const auto& t : around) {
            int v[4] = {c[t[0]], c[t[1]], c[t[2]], c[t[3]]};
            const Vec3d a = nodes[v[0]];
            if ((nodes[v[1]] - a).dot((nodes[v[2]] - a).cross(nodes[v[3]] - a)) < 0)
              std::swap(v[2], v[3]);
            for (int x : v) tetrahedra += std::to_string(x) + " ";
            tetrahedra += " ";
            for (int p = 0; p < 4; ++p)
              for (int q = p + 1; q < 4; ++q)
                edgeList.push_back({std::min(v[p], v[q]), std::max(v[p], v[q])});
          }
        }
    std::sort(edgeList.begin(), edgeList.end());
    edgeList.erase(std::unique(edgeList.begin(), edgeList.end()), edgeList.end());
    for (const auto& e : edgeList)
      edges += std::to_string(e[0]) + " " + std::to_string(e[1]) + "  ";
  }
};

// Points inside the cube, one on a face, one on an inner vertex.
const char* kEmbedded = "0.3 0.4 0.5  1.7 0.2 1.1  1 1 1  0.5 1.5 2  1.99 1.2 0.01  1.25 1.5 0.75";

std::string meshScene(const std::string& topology, const std::string& embedded,
                      const std::string& mappingAttributes = "", const std::string& extra = "") {
  const CubeMesh mesh;
  return R"(<Node name="root" gravity="0 0 0">
      <MechanicalObject name="dofs" position=")" +
         mesh.points + R"("/>
      )" +
         topology + R"(
      <Node name="Embedded">
        <MechanicalObject name="points" position=")" +
         embedded + R"("/>
        <BarycentricMapping )" +
         mappingAttributes + R"(/>
        )" +
         extra + R"(
      </Node>
    </Node>)";
}

std::string tetrahedra() {
  return R"(<MeshTopology name="mesh" tetrahedra=")" + CubeMesh().tetrahedra + R"("/>)";
}
const char* kGrid = R"(<RegularGridTopology name="grid" n="3 3 3" min="0 0 0" max="2 2 2"/>)";

// Each output point's weights, read from J (the x rows): (point -> sum, min, max).
struct WeightStats {
  double minWeight = 1e300, maxWeight = -1e300, worstSum = 0;
};
WeightStats weightsOf(PointMapping& mapping) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> J = mapping.jacobian();
  WeightStats s;
  for (Eigen::Index row = 0; row < J.rows(); row += 3) {
    double sum = 0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(J, row); e; ++e) {
      s.minWeight = std::min(s.minWeight, e.value());
      s.maxWeight = std::max(s.maxWeight, e.value());
      sum += e.value();
    }
    s.worstSum = std::max(s.worstSum, std::abs(sum - 1));
  }
  return s;
}

// Moves the mesh by x -> A x + b and maps: the embedded points must move the same way.
double patchTestError(PointMapping& mapping, const std::vector<Vec3d>& embedded) {
  const Mat3d A = Mat3d::Identity() + 0.3 * Mat3d::Random();
  const Vec3d b(0.5, -1, 2);
  auto& x = mapping.input()->writeCoord(VecId::position());
  for (Vec3d& p : x) p = A * p + b;
  mapping.applyPositions(VecId::position(), VecId::position());
  const auto& out = mapping.output()->readCoord(VecId::position());
  double worst = 0;
  for (std::size_t k = 0; k < embedded.size(); ++k)
    worst = std::max(worst, (out[k] - (A * embedded[k] + b)).norm());
  return worst;
}

std::vector<Vec3d> parsePoints(const std::string& text) {
  std::istringstream in(text);
  std::vector<Vec3d> points;
  Vec3d p;
  while (in >> p.x() >> p.y() >> p.z()) points.push_back(p);
  return points;
}

TEST(BarycentricMapping, TetrahedraWeightsAreConvexAndReproduceLinearMotions) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(meshScene(tetrahedra(), kEmbedded))) << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  auto* mapping = findInScene<PointMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  // The first apply puts the points where the scene put them.
  const auto embedded = parsePoints(kEmbedded);
  const auto& out = mapping->output()->readCoord(VecId::position());
  for (std::size_t k = 0; k < embedded.size(); ++k)
    EXPECT_LT((out[k] - embedded[k]).norm(), 1e-15) << k;
  const WeightStats w = weightsOf(*mapping);
  EXPECT_GE(w.minWeight, -1e-12);
  EXPECT_LE(w.maxWeight, 1 + 1e-12);
  EXPECT_LT(w.worstSum, 1e-14);
  expectConsistentMapping(*mapping, 2.0);
  EXPECT_LT(patchTestError(*mapping, embedded), 1e-14);
}

TEST(BarycentricMapping, RegularGridHexahedraGiveTrilinearWeights) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(meshScene(kGrid, kEmbedded))) << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  auto* mapping = findInScene<PointMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  const WeightStats w = weightsOf(*mapping);
  EXPECT_GE(w.minWeight, -1e-12);
  EXPECT_LT(w.worstSum, 1e-14);
  // The first point (0.3, 0.4, 0.5) is in the first cell: the weight of its corner (1, 1, 1)
  // is u v w.
  const Eigen::MatrixXd J = mapping->jacobian();
  EXPECT_NEAR(J(0, 3 * (1 + 3 + 9)), 0.3 * 0.4 * 0.5, 1e-15);
  EXPECT_NEAR(J(0, 0), 0.7 * 0.6 * 0.5, 1e-15);
  expectConsistentMapping(*mapping, 2.0);
  EXPECT_LT(patchTestError(*mapping, parsePoints(kEmbedded)), 1e-14);
}

TEST(BarycentricMapping, PointsOutsideFollowTheNearestElementWithAWarning) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(meshScene(tetrahedra(), "1 1 1  2.5 1 1  1 -0.25 1")))
      << problems(scene.log());
  EXPECT_NE(problems(scene.log())
                .find("2 of the 3 output points are outside the input mesh and "
                      "follow their nearest element (the farthest, point 1, "
                      "is at 0.500000)"),
            std::string::npos)
      << problems(scene.log());
  auto* mapping = findInScene<PointMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  // Extrapolated, they still move with linear motions of the mesh.
  EXPECT_LT(patchTestError(*mapping, parsePoints("1 1 1  2.5 1 1  1 -0.25 1")), 1e-13);
}

TEST(BarycentricMapping, ReportsAMissingOrSurfaceTopology) {
  Runtime runtime;
  Scene none(runtime), surface(runtime);
  EXPECT_FALSE(none.loadString(meshScene("", kEmbedded)));
  EXPECT_NE(problems(none.log()).find("no topology in /root"), std::string::npos)
      << problems(none.log());
  EXPECT_FALSE(surface.loadString(meshScene(R"(<MeshTopology triangles="0 1 3"/>)", kEmbedded)));
  EXPECT_NE(problems(surface.log()).find("has no tetrahedra nor hexahedra"), std::string::npos)
      << problems(surface.log());
}

// The cube as an elastic body (springs on the tetrahedra's edges, 27 kg), falling or loaded,
// with an embedded surface; `load` goes into the surface's node, `bodyLoad` into the body's.
std::string bodyScene(const std::string& gravity, const std::string& load,
                      const std::string& bodyLoad) {
  const CubeMesh mesh;
  return R"(<Node name="root" gravity=")" + gravity + R"(" dt="0.01">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <CGLinearSolver iterations="500" tolerance="1e-14" threshold="1e-40"/>
      <MechanicalObject name="dofs" position=")" +
         mesh.points + R"("/>
      )" +
         tetrahedra() + R"(
      <UniformMass totalMass="27"/>
      <TestSprings stiffness="2000" edges=")" +
         mesh.edges + R"("/>
      )" +
         bodyLoad + R"(
      <Node name="Surface">
        <MechanicalObject name="points" position=")" +
         kEmbedded + R"("/>
        <BarycentricMapping input="@.." output="@."/>
        )" +
         load + R"(
      </Node>
    </Node>)";
}

TEST(BarycentricMapping, AFallingBodyCarriesItsEmbeddedSurface) {
  Runtime runtime;
  runtime.factory().add("TestSprings", "test").with<CorrectSprings>();
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(bodyScene("0 0 -9.81", "", ""))) << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  const auto x0 = positionsAt(scene, "/root/Surface/points");
  const int steps = 25;
  for (int i = 0; i < steps; ++i) ASSERT_TRUE(scene.step()) << problems(scene.log());
  // A uniform field does not deform the body: every point falls by g t (t + h) / 2 (backward
  // Euler), the embedded ones too.
  const double t = steps * 0.01, drop = 9.81 * t * (t + 0.01) / 2;
  const auto x = positionsAt(scene, "/root/Surface/points");
  for (std::size_t k = 0; k < x.size(); ++k)
    EXPECT_NEAR(x[k], x0[k] - (k % 3 == 2 ? drop : 0.0), 1e-10) << k;
}

TEST(BarycentricMapping, ForcesOnTheSurfaceActOnTheBodyThroughJT) {
  Runtime runtime;
  runtime.factory().add("TestSprings", "test").with<CorrectSprings>();
  // Forces on three embedded points...
  const std::string onSurface =
      R"(<ConstantForceField indices="0 1 5" forces="10 0 -5  0 30 0  -8 4 12"/>)";
  Scene mapped(runtime);
  ASSERT_TRUE(mapped.loadString(bodyScene("0 0 0", onSurface, ""))) << problems(mapped.log());
  // ... are the forces J^T F on the body's points.
  auto* mapping = findInScene<PointMapping>(mapped.root());
  ASSERT_NE(mapping, nullptr);
  std::vector<Vec3d> F(mapping->output()->size(), Vec3d::Zero());
  F[0] = Vec3d(10, 0, -5);
  F[1] = Vec3d(0, 30, 0);
  F[5] = Vec3d(-8, 4, 12);
  std::vector<Vec3d> JTF(mapping->input()->size(), Vec3d::Zero());
  mapping->applyJT(JTF, F);
  std::ostringstream forces;
  forces.precision(17);
  for (const Vec3d& f : JTF) forces << f.x() << ' ' << f.y() << ' ' << f.z() << "  ";
  Scene direct(runtime);
  ASSERT_TRUE(direct.loadString(
      bodyScene("0 0 0", "", R"(<ConstantForceField forces=")" + forces.str() + R"("/>)")))
      << problems(direct.log());

  for (int i = 0; i < 20; ++i) ASSERT_TRUE(mapped.step() && direct.step());
  const auto a = positionsAt(mapped, "/root/dofs"), b = positionsAt(direct, "/root/dofs");
  ASSERT_EQ(a.size(), b.size());
  double moved = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k], b[k], 1e-10) << k;
    moved = std::max(moved, std::abs(a[k] - CubeMesh().nodes[k / 3][k % 3]));
  }
  EXPECT_GT(moved, 1e-3);  // the load did deform and move the body
}

TEST(BarycentricMapping, SpringsBetweenEmbeddedPointsAssembleAsJTKJ) {
  Runtime runtime;
  runtime.factory().add("TestSprings", "test").with<CorrectSprings>();
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(meshScene(
      tetrahedra() + R"(<UniformMass totalMass="2"/><FixedProjectiveConstraint indices="0 4"/>)",
      kEmbedded, "",
      R"(<UniformMass totalMass="0.5"/><TestSprings stiffness="30" edges="0 1  1 2  2 3  3 4  4 5  0 5  1 4"/>)")))
      << problems(scene.log());
  // Deform the mesh so that the springs pull.
  auto* mapping = findInScene<PointMapping>(scene.root());
  auto& x = mapping->input()->writeCoord(VecId::position());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] += 0.1 * Vec3d(std::sin(3.0 * i), std::cos(5.0 * i), std::sin(7.0 * i + 1));
  const SystemCheckReport r = measureSystem(scene, 1.0, -0.5, true);
  EXPECT_LT(r.assembled, 1e-14);
  // A linear mapping: the mapped stiffness is exactly J^T K J, pulled springs or not.
  EXPECT_LT(r.stiffness, 1e-7);
}

}  // namespace
}  // namespace stroma::test
