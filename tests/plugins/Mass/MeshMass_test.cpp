// SPDX-License-Identifier: MIT
// DiagonalMass and MeshMatrixMass: total masses, the consistent matrices of a tetrahedron and
// a hexahedron against their closed forms, lumped = row sums, the assembled matrix against
// addMDx, free fall, runtime changes, and bad input.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/Mass.h"

namespace stroma::test {
namespace {

const char* kTetra = R"(
<Node name="root" gravity="0 -10 0">
  <MeshTopology name="topo" tetrahedra="0 1 2 3"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
  <MASS name="mass" ATTRIBUTES/>
</Node>)";

std::string withMass(std::string scene, const std::string& mass, const std::string& attributes) {
  scene.replace(scene.find("MASS"), 4, mass);
  scene.replace(scene.find("ATTRIBUTES"), 10, attributes);
  return scene;
}

TEST(MeshMatrixMass, ConsistentTetrahedronMatrix) {
  SceneHolder s;
  ASSERT_TRUE(s.load(withMass(kTetra, "MeshMatrixMass", R"(massDensity="2")")));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::MatrixXd M = check.assembled(1, 0, 0);
  // rho V / 20 (1 + delta_ij) on each coordinate, V = 1/6.
  const double a = 2.0 / 6 / 20;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          EXPECT_NEAR(M(3 * i + k, 3 * j + l), k == l ? a * (i == j ? 2 : 1) : 0, 1e-15);
  EXPECT_LT((check.matrixFreeMass() - M).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_FALSE(s.get<BaseMass>("@mass")->isDiagonal());
  // Gravity is the consistent load: rho V / 4 g per point, total rho V g.
  const Eigen::VectorXd f = check.force();
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(f[3 * i + 1], -10 * 2.0 / 6 / 4, 1e-14);
  // Kinetic energy of a uniform velocity u: m |u|^2 / 2.
  MechanicalOperations mop(s.root(), s.scene().timing());
  s.set("@dofs.velocity", "1 2 0  1 2 0  1 2 0  1 2 0");
  EXPECT_NEAR(mop.kineticEnergy(), 0.5 * (2.0 / 6) * 5, 1e-14);
}

TEST(MeshMatrixMass, LumpingGivesTheRowSums) {
  SceneHolder s;
  ASSERT_TRUE(s.load(withMass(kTetra, "MeshMatrixMass", R"(massDensity="2" lumping="1")")));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::MatrixXd M = check.assembled(1, 0, 0);
  EXPECT_TRUE(M.isApprox((2.0 / 6 / 4) * Eigen::MatrixXd::Identity(12, 12), 1e-14));
  EXPECT_LT((check.matrixFreeMass() - M).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_TRUE(s.get<BaseMass>("@mass")->isDiagonal());
}

TEST(DiagonalMass, TetrahedronAndTotalMass) {
  SceneHolder s;
  ASSERT_TRUE(s.load(withMass(kTetra, "DiagonalMass", R"(massDensity="3")")));
  ForceFieldChecker check(s.scene(), s.root());
  EXPECT_TRUE(
      check.assembled(1, 0, 0).isApprox((3.0 / 6 / 4) * Eigen::MatrixXd::Identity(12, 12), 1e-14));
  // totalMass replaces the density: 5 kg over the volume.
  s.set("@mass.totalMass", "5");
  EXPECT_NEAR(check.assembled(1, 0, 0).trace() / 3, 5, 1e-13);
  EXPECT_NEAR(check.force().sum(), -10 * 5, 1e-12);
  EXPECT_LT((check.finiteDifferenceForce() - check.force()).norm(), 1e-6);
}

// Unit cube of one hexahedron: M_ij = rho V (1/3)^s (1/6)^(3 - s), s the number of coordinates
// the two corners share (tensor product of the 1D linear element's L/6 [2 1; 1 2]).
TEST(MeshMatrixMass, ConsistentHexahedronMatrix) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <RegularGridTopology name="grid" n="2 2 2" min="0 0 0" max="2 1 1"/>
  <MechanicalObject name="dofs" position="@grid.position"/>
  <MeshMatrixMass name="mass" massDensity="1.5"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::MatrixXd M = check.assembled(1, 0, 0);
  const auto x = numbers(s.text("@dofs.position"));
  const double rhoV = 1.5 * 2;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      int same = 0;
      for (int d = 0; d < 3; ++d) same += x[3 * i + d] == x[3 * j + d];
      EXPECT_NEAR(M(3 * i, 3 * j), rhoV * std::pow(1.0 / 3, same) * std::pow(1.0 / 6, 3 - same),
                  1e-14)
          << i << " " << j;
    }
  EXPECT_NEAR(M.sum() / 3, rhoV, 1e-13);
  EXPECT_LT((check.matrixFreeMass() - M).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(DiagonalMass, DistortedHexahedronKeepsItsVolume) {
  // A sheared and stretched brick: volume = det of its edge vectors = 2 * 3 * 0.5.
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <MeshTopology name="topo" hexahedra="0 1 2 3 4 5 6 7"/>
  <MechanicalObject name="dofs" position="0 0 0  2 0 0  2.5 3 0  0.5 3 0
                                          0.3 0.2 0.5  2.3 0.2 0.5  2.8 3.2 0.5  0.8 3.2 0.5"/>
  <DiagonalMass name="mass" massDensity="4"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::MatrixXd M = check.assembled(1, 0, 0);
  EXPECT_NEAR(M.trace() / 3, 4 * 3.0, 1e-12);
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(M(3 * i, 3 * i), 4 * 3.0 / 8, 1e-12);  // parallelepiped
}

TEST(MeshMatrixMass, TrianglesCarryMassByArea) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <MeshTopology name="topo" triangles="0 1 2  0 2 3"/>
  <MechanicalObject name="dofs" position="0 0 0  2 0 0  2 3 0  0 3 0"/>
  <MeshMatrixMass name="mass" totalMass="12"/>
</Node>)"));
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::MatrixXd M = check.assembled(1, 0, 0);
  EXPECT_NEAR(M.sum() / 3, 12, 1e-12);
  // Density 12 / 6 = 2 per unit area; triangle 0-1-2 of area 3: M_01 = 2 * 3 / 12.
  EXPECT_NEAR(M(0, 3), 0.5, 1e-14);
  EXPECT_NEAR(M(3, 3), 2 * 3.0 / 6, 1e-14);  // point 1 is in one triangle: 2 rho A / 12
}

TEST(MeshMatrixMass, FreeFallIsExactWithTheConsistentMatrix) {
  // Gravity is M times g on every point, so every point falls as a free point would:
  // x_n = x_0 + h^2 g n (n + 1) / 2 for backward Euler.
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 -9.81" dt="0.02">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="200" tolerance="1e-15" threshold="0"/>
  <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
  <MechanicalObject name="dofs" position="@grid.position"/>
  <MeshMatrixMass name="mass" massDensity="7"/>
</Node>)"));
  const auto x0 = numbers(s.text("@dofs.position"));
  const int n = 20;
  ASSERT_TRUE(s.step(n));
  const auto x = numbers(s.text("@dofs.position"));
  for (std::size_t i = 0; i < x.size(); i += 3) {
    EXPECT_NEAR(x[i], x0[i], 1e-12);
    EXPECT_NEAR(x[i + 2], x0[i + 2] - 9.81 * 0.02 * 0.02 * n * (n + 1) / 2, 1e-10);
  }
}

// The scene with an explicit solver in the root node.
std::string explicitScene(const std::string& attributes) {
  std::string scene = withMass(kTetra, "MeshMatrixMass", attributes);
  return scene.insert(scene.find('>', scene.find("<Node")) + 1, "<EulerExplicitSolver/>");
}

TEST(MeshMatrixMass, ExplicitSolverNeedsLumping) {
  SceneHolder s;
  ASSERT_TRUE(s.load(explicitScene("")));
  EXPECT_FALSE(s.scene().step());
  EXPECT_NE(findError(s.scene().log(), "MeshMatrixMass").text, "") << describe(s.scene().log());
  SceneHolder t;
  ASSERT_TRUE(t.load(explicitScene(R"(lumping="1")")));
  EXPECT_TRUE(t.step(3));
}

TEST(MeshMatrixMass, DensityChangedWhileRunningActsAtTheNextStep) {
  SceneHolder s;
  ASSERT_TRUE(s.load(withMass(kTetra, "MeshMatrixMass", R"(massDensity="1")")));
  ForceFieldChecker check(s.scene(), s.root());
  const double before = check.assembled(1, 0, 0).sum();
  s.set("@mass.massDensity", "3");
  EXPECT_NEAR(check.assembled(1, 0, 0).sum(), 3 * before, 1e-13);
  s.set("@mass.lumping", "1");
  EXPECT_NEAR(check.assembled(1, 0, 0).sum(), 3 * before, 1e-13);
  EXPECT_TRUE(s.get<BaseMass>("@mass")->isDiagonal());
}

TEST(MeshMass, BadInputIsReported) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/><DiagonalMass/></Node>)",
                          {"needs a topology"})
                .field,
            "topology");
  SceneHolder t;
  t.loadFailing(R"(<Node><MeshTopology tetrahedra="0 1 2 7"/>
<MechanicalObject position="0 0 0  1 0 0  0 1 0  0 0 1"/><MeshMatrixMass/></Node>)",
                {"1 tetrahedra", "out of range of the 4 points", "element 0: 0 1 2 7"});
  SceneHolder u;
  u.loadFailing(R"(<Node><MeshTopology tetrahedra="0 1 2 3"/>
<MechanicalObject position="0 0 0  1 0 0  2 0 0  3 0 0"/><DiagonalMass/></Node>)",
                {"no volume"});
}

}  // namespace
}  // namespace stroma::test
