// SPDX-License-Identifier: MIT
// TetrahedronFEMForceField: the generic force-field checks for each rotation method (with the
// documented bounds where the corotational force or tangent is not exact), the patch test, the
// SOFA names, the hexahedra split, run-time material changes and bad input. The cantilever and
// thread-count tests of both FEM force fields are in FemValidation_test.cpp.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "CorotationalBounds.h"
#include "FemTestScenes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

/// 2 x 2 x 2 cells of the unit cube, its interior point moved, split into 48 tetrahedra.
FemMesh smallTetrahedralMesh() {
  FemMesh mesh = makeBoxMesh(Vec3d(1, 1, 1), Vec3i(2, 2, 2));
  distortInterior(mesh, Vec3d(1, 1, 1), 0.5, 0.15);
  return mesh;
}

std::string fieldXml(const std::string& className, const std::string& attributes) {
  return "<" + className + " name=\"fem\" youngModulus=\"1000\" poissonRatio=\"0.3\" " +
         attributes + "/>";
}

std::string tetraScene(const std::string& method) {
  return femScene(smallTetrahedralMesh(), "tetrahedra",
                  fieldXml("TetrahedronFEMForceField", "method=\"" + method + "\""));
}

// --- Generic force-field checks ------------------------------------------------------------

TEST(TetrahedronFEMForceField, SmallIsLinearElasticityExactly) {
  // Linear: f = -Ke (x - X) is exactly -dE/dx and K is exact; not rotation invariant.
  checkForceField(tetraScene("small"), {.hasEnergy = true, .rotationInvariant = false});
}

// The rotating methods, at positions perturbed by p (relative to the spacing, so strains of
// order p): the tangent R Ke R^T ignores dR/dx, an error of relative size O(p) (kernels
// README, "Known limits"); everything else holds to round-off.
struct RotatingCase {
  const char* method;
  bool exactEnergy;  // f = -dE/dx exactly (polar, svd); O(p) for large
};

class RotatingMethods : public ::testing::TestWithParam<RotatingCase> {};

TEST_P(RotatingMethods, PassTheForceFieldTestWithinTheCorotationalBounds) {
  const RotatingCase c = GetParam();
  const double p = 1e-3;
  ForceFieldTestOptions options{.rotationInvariant = true, .perturbation = p};
  const ForceFieldTestReport r = measureForceField(tetraScene(c.method), options);
  ASSERT_TRUE(r.failure.empty()) << r.describe();
  // Measured at p = 1e-3 on this mesh: energy error 6.2e-5 (large), 1.3e-8 (polar, svd: the
  // finite-difference truncation); addDForce error 8.2e-4 (large), 5.4e-4 (polar, svd); net
  // moment 3.0e-5 (large); everything else below 1e-12.
  expectCorotationalBounds(r, p, c.exactEnergy);
}

TEST_P(RotatingMethods, TangentErrorIsFirstOrderInTheStrain) {
  // The O(p) above is the dR/dx term, not a bug: it shrinks tenfold with the strain.
  const RotatingCase c = GetParam();
  ForceFieldTestOptions options{.rotationInvariant = false, .perturbation = 1e-2};
  const ForceFieldTestReport coarse = measureForceField(tetraScene(c.method), options);
  options.perturbation = 1e-3;
  const ForceFieldTestReport fine = measureForceField(tetraScene(c.method), options);
  ASSERT_TRUE(coarse.failure.empty() && fine.failure.empty());
  const double order = std::log10(coarse.dForceError / fine.dForceError);
  EXPECT_NEAR(order, 1.0, 0.2) << coarse.describe() << fine.describe();
}

void PrintTo(const RotatingCase& c, std::ostream* out) { *out << "method " << c.method; }

INSTANTIATE_TEST_SUITE_P(TetrahedronFEMForceField, RotatingMethods,
                         ::testing::Values(RotatingCase{"large", false},
                                           RotatingCase{"polar", true}, RotatingCase{"svd", true}),
                         [](const auto& info) { return std::string(info.param.method); });

// --- Patch test ----------------------------------------------------------------------------

// The linear field of REFERENCES.md ("Patch test"): u = 1e-3 A x with A symmetric, constant
// strains 1e-3 (engineering shear).
Vec3d patchDisplacement(const Vec3d& x) {
  Eigen::Matrix3d A;
  A << 2, 1, 1, 1, 2, 1, 1, 1, 2;
  return 0.5e-3 * A * x;
}

bool onBoundary(const Vec3d& p) {
  for (int a = 0; a < 3; ++a)
    if (std::abs(p[a]) < 1e-12 || std::abs(p[a] - 1) < 1e-12) return true;
  return false;
}

TEST(TetrahedronFEMForceField, PassesThePatchTestOnADistortedMesh) {
  // 3 x 3 x 3 cells, the 8 interior points moved by up to 20 % of the spacing: the interior
  // displacements solved with the boundary ones imposed reproduce the linear field.
  FemMesh mesh = makeBoxMesh(Vec3d(1, 1, 1), Vec3i(3, 3, 3));
  distortInterior(mesh, Vec3d(1, 1, 1), 1.0 / 3, 0.2);
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(
      scene, femScene(mesh, "tetrahedra",
                      "<TetrahedronFEMForceField youngModulus=\"1e6\" poissonRatio=\"0.25\" "
                      "method=\"small\"/>")));
  const Eigen::SparseMatrix<double> K = assembleStiffness(scene);
  std::vector<int> interior, boundary;
  for (int i = 0; i < static_cast<int>(mesh.points.size()); ++i)
    (onBoundary(mesh.points[i]) ? boundary : interior).push_back(i);
  ASSERT_EQ(interior.size(), 8u);
  // Equilibrium of the interior: K_II u_I = -K_IB u_B (K dense: 192 dofs).
  const Eigen::MatrixXd Kd(K);
  const auto rows = [](const std::vector<int>& points) {
    std::vector<int> r;
    for (int p : points)
      for (int k = 0; k < 3; ++k) r.push_back(3 * p + k);
    return r;
  };
  const std::vector<int> I = rows(interior), B = rows(boundary);
  Eigen::VectorXd uB(B.size()), exactI(I.size());
  for (std::size_t k = 0; k < boundary.size(); ++k)
    uB.segment<3>(3 * k) = patchDisplacement(mesh.points[boundary[k]]);
  for (std::size_t k = 0; k < interior.size(); ++k)
    exactI.segment<3>(3 * k) = patchDisplacement(mesh.points[interior[k]]);
  const Eigen::MatrixXd KII = Kd(I, I), KIB = Kd(I, B);
  const Eigen::VectorXd uI = KII.ldlt().solve(-KIB * uB);
  EXPECT_LT((uI - exactI).norm() / exactI.norm(), 1e-10);
}

TEST(TetrahedronFEMForceField, RotatingMethodsPassThePatchTestInEquilibrium) {
  // The pure strain field, rotated by 50 degrees: polar and svd find R exactly (R^T F is the
  // symmetric stretch), so the interior points are in equilibrium to round-off.
  FemMesh mesh = makeBoxMesh(Vec3d(1, 1, 1), Vec3i(3, 3, 3));
  distortInterior(mesh, Vec3d(1, 1, 1), 1.0 / 3, 0.2);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.87, Vec3d(1, 2, 3).normalized()).toRotationMatrix();
  for (const char* method : {"polar", "svd"}) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, femScene(mesh, "tetrahedra",
                                            "<TetrahedronFEMForceField youngModulus=\"1e6\" "
                                            "poissonRatio=\"0.25\" method=\"" +
                                                std::string(method) + "\"/>")));
    auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs");
    auto& x = dofs->writeCoord(VecId::position());
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = Q * (mesh.points[i] + patchDisplacement(mesh.points[i]));
    const Eigen::VectorXd f = computeForces(scene);
    double interiorForce = 0, boundaryForce = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      (onBoundary(mesh.points[i]) ? boundaryForce : interiorForce) +=
          f.segment<3>(3 * i).squaredNorm();
    EXPECT_LT(std::sqrt(interiorForce / boundaryForce), 1e-10) << method;
  }
}

// --- SOFA's names and meshes ---------------------------------------------------------------

Eigen::VectorXd forcesOf(const std::string& xml, const std::vector<Vec3d>& positions) {
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(scene, xml)) return {};
  auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs");
  dofs->writeCoord(VecId::position()) = positions;
  return computeForces(scene);
}

std::vector<Vec3d> deformed(const FemMesh& mesh) {
  std::vector<Vec3d> x = mesh.points;
  for (Vec3d& p : x) p += Vec3d(0.1 * p.y() * p.z(), -0.05 * p.x(), 0.2 * p.x() * p.x());
  return x;
}

TEST(TetrahedronFEMForceField, SofaSecondNamesAreTheSameModel) {
  const FemMesh mesh = smallTetrahedralMesh();
  const std::vector<Vec3d> x = deformed(mesh);
  auto forces = [&](const std::string& className, const std::string& attributes) {
    return forcesOf(femScene(mesh, "tetrahedra", fieldXml(className, attributes)), x);
  };
  const Eigen::VectorXd large = forces("TetrahedronFEMForceField", "method=\"large\"");
  const Eigen::VectorXd polar = forces("TetrahedronFEMForceField", "method=\"polar\"");
  ASSERT_GT(large.norm(), 0);
  // Default method: large, as SOFA's three components.
  EXPECT_EQ(forces("TetrahedronFEMForceField", ""), large);
  EXPECT_EQ(forces("TetrahedralCorotationalFEMForceField", ""), large);
  EXPECT_EQ(forces("FastTetrahedralCorotationalForceField", ""), large);
  EXPECT_EQ(forces("FastTetrahedralCorotationalForceField", "method=\"qr\""), large);
  EXPECT_EQ(forces("FastTetrahedralCorotationalForceField", "method=\"polar2\""), polar);
  EXPECT_NE(large, polar);
}

TEST(TetrahedronFEMForceField, SplitsAHexahedralTopologyIntoSixTetrahedraEach) {
  // SOFA's TetrahedronFEMForceField on hexahedra: the same forces as the explicit split.
  const FemMesh mesh = smallTetrahedralMesh();
  const std::vector<Vec3d> x = deformed(mesh);
  const std::string field = fieldXml("TetrahedronFEMForceField", "method=\"polar\"");
  const Eigen::VectorXd fromHexahedra = forcesOf(femScene(mesh, "hexahedra", field), x);
  const Eigen::VectorXd fromTetrahedra = forcesOf(femScene(mesh, "tetrahedra", field), x);
  ASSERT_GT(fromTetrahedra.norm(), 0);
  EXPECT_EQ(fromHexahedra, fromTetrahedra);
}

TEST(TetrahedronFEMForceField, TakesTheTetrahedraOfTheNodeWhenAGridIsThereToo) {
  // SOFA's scenes put a grid (hexahedra) and, filled by a Hexa2TetraTopologicalMapping, a
  // tetrahedron container in one node: the force field must take the container's tetrahedra,
  // wherever the grid is. The container here holds half of the tetrahedra, so that the split
  // grid would give other forces.
  const FemMesh mesh = smallTetrahedralMesh();
  FemMesh half = mesh;
  half.tetrahedra.resize(mesh.tetrahedra.size() / 2);
  const std::vector<Vec3d> x = deformed(mesh);
  const std::string field = fieldXml("TetrahedronFEMForceField", "method=\"large\"");
  const std::string grid =
      "<MeshTopology name=\"grid\" hexahedra=\"" + elementsText(mesh.hexahedra) + "\"/>";
  const std::string container = "<TetrahedronSetTopologyContainer name=\"tetra\" tetrahedra=\"" +
                                elementsText(half.tetrahedra) + "\"/>";
  const std::string dofs =
      "<MechanicalObject name=\"dofs\" position=\"" + pointsText(mesh.points) + "\"/>";
  auto scene = [&](const std::string& topologies) {
    return "<Node name=\"root\" gravity=\"0 0 0\"><Node name=\"body\">" + topologies + dofs +
           field + "</Node></Node>";
  };
  const Eigen::VectorXd expected = forcesOf(femScene(half, "tetrahedra", field), x);
  ASSERT_GT(expected.norm(), 0);
  EXPECT_EQ(forcesOf(scene(grid + container), x), expected);
  EXPECT_EQ(forcesOf(scene(container + grid), x), expected);
  // Without the container, the grid's hexahedra are split.
  EXPECT_EQ(forcesOf(scene(grid), x), forcesOf(femScene(mesh, "tetrahedra", field), x));
}

// --- Material: per element, and changed while running -------------------------------------

TEST(TetrahedronFEMForceField, TakesOneYoungModulusPerElement) {
  const FemMesh mesh = smallTetrahedralMesh();
  const std::vector<Vec3d> x = deformed(mesh);
  std::string same, doubled;
  for (std::size_t e = 0; e < mesh.tetrahedra.size(); ++e) {
    same += "1000 ";
    doubled += "2000 ";
  }
  auto forces = [&](const std::string& youngModulus) {
    return forcesOf(femScene(mesh, "tetrahedra",
                             "<TetrahedronFEMForceField youngModulus=\"" + youngModulus +
                                 "\" poissonRatio=\"0.3\" method=\"polar\"/>"),
                    x);
  };
  const Eigen::VectorXd uniform = forces("1000");
  EXPECT_EQ(forces(same), uniform);
  EXPECT_LT((forces(doubled) - 2 * uniform).norm(), 1e-13 * uniform.norm());
}

TEST(TetrahedronFEMForceField, MaterialChangedWhileRunningTakesEffectAtTheNextForce) {
  const FemMesh mesh = smallTetrahedralMesh();
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, tetraScene("large")));
  objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs")->writeCoord(VecId::position()) =
      deformed(mesh);
  Base* fem = objectAt<Base>(scene, "@/body/fem");
  const Eigen::VectorXd before = computeForces(scene);
  std::string why;
  ASSERT_TRUE(fem->findData("youngModulus")->read("3000", why)) << why;
  const Eigen::VectorXd stiffer = computeForces(scene);
  EXPECT_LT((stiffer - 3 * before).norm(), 1e-13 * stiffer.norm());
  // Another Poisson's ratio gives other forces (not a multiple).
  ASSERT_TRUE(fem->findData("poissonRatio")->read("0.1", why)) << why;
  const Eigen::VectorXd softer = computeForces(scene);
  EXPECT_GT((softer - stiffer.dot(softer) / stiffer.squaredNorm() * stiffer).norm(),
            1e-3 * softer.norm());
  // An invalid value (0.5 is in the field's range but incompressible) is a warning, once,
  // and the previous material stays.
  ASSERT_TRUE(fem->findData("poissonRatio")->read("0.5", why)) << why;
  EXPECT_EQ(computeForces(scene), softer);
  EXPECT_EQ(computeForces(scene), softer);
  std::size_t warnings = 0;
  for (const Message& m : scene.log().messages())
    if (m.level == MessageLevel::warning) {
      ++warnings;
      EXPECT_EQ(m.field, "poissonRatio");
      EXPECT_NE(m.text.find("0.5"), std::string::npos) << m.text;
    }
  EXPECT_EQ(warnings, 1u);
}

TEST(TetrahedronFEMForceField, FollowsTheTopologyWhenItsTetrahedraChange) {
  const FemMesh mesh = smallTetrahedralMesh();
  FemMesh half = mesh;
  half.tetrahedra.resize(mesh.tetrahedra.size() / 2);
  const std::vector<Vec3d> x = deformed(mesh);
  const std::string field = fieldXml("TetrahedronFEMForceField", "method=\"polar\"");
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, femScene(mesh, "tetrahedra", field)));
  objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs")->writeCoord(VecId::position()) = x;
  const Eigen::VectorXd all = computeForces(scene);
  std::string why;
  ASSERT_TRUE(objectAt<Base>(scene, "@/body/mesh")
                  ->findData("tetrahedra")
                  ->read(elementsText(half.tetrahedra), why))
      << why;
  const Eigen::VectorXd fewer = computeForces(scene);
  EXPECT_EQ(fewer, forcesOf(femScene(half, "tetrahedra", field), x));
  EXPECT_NE(fewer, all);
}

// --- Bad input -----------------------------------------------------------------------------

/// Loads a one-node scene with `tetrahedra` on `points`; returns the log's errors and warnings.
std::string loadMessages(const std::string& points, const std::string& tetrahedra,
                         const std::string& attributes, bool& loaded) {
  Runtime runtime;
  Scene scene(runtime);
  loaded =
      scene.loadString("<Node name=\"root\"><MeshTopology tetrahedra=\"" + tetrahedra +
                       "\"/><MechanicalObject position=\"" + points +
                       "\"/><TetrahedronFEMForceField name=\"fem\" " + attributes + "/></Node>");
  std::string text;
  for (const Message& m : scene.log().messages())
    if (m.level != MessageLevel::info)
      text += "[" + m.componentPath + " " + m.field + "] " + m.text + "\n";
  return text;
}

const char* kTwoTetrahedraPoints = "0 0 0  1 0 0  0 1 0  0 0 1  1 1 1";

TEST(TetrahedronFEMForceField, ReportsDegenerateRestTetrahedraByIndex) {
  bool loaded = true;
  // Element 1 is flat: its four points lie in the plane z = 0.
  const std::string messages =
      loadMessages("0 0 0  1 0 0  0 1 0  0 0 1  1 1 0", "0 1 2 3  0 1 2 4", "", loaded);
  EXPECT_FALSE(loaded);
  EXPECT_NE(messages.find("[/root/fem topology]"), std::string::npos) << messages;
  EXPECT_NE(messages.find("degenerate"), std::string::npos) << messages;
  EXPECT_NE(messages.find("elements 1"), std::string::npos) << messages;
}

TEST(TetrahedronFEMForceField, WarnsAboutInvertedRestTetrahedraByIndexAndUsesThem) {
  bool loaded = false;
  // Element 1 is (0, 2, 1, 4): negative volume.
  const std::string messages = loadMessages(kTwoTetrahedraPoints, "0 1 2 3  0 2 1 4", "", loaded);
  EXPECT_TRUE(loaded) << messages;
  EXPECT_NE(messages.find("inverted"), std::string::npos) << messages;
  EXPECT_NE(messages.find("elements 1;"), std::string::npos) << messages;
}

TEST(TetrahedronFEMForceField, ReportsBadMaterialAndIndices) {
  struct Case {
    const char* tetrahedra;
    const char* attributes;
    const char* needle;
  } cases[] = {
      {"0 1 2 3  1 2 3 4", "youngModulus=\"1 2 3\"",
       "[/root/fem youngModulus] expected one value or one per element (2 tetrahedra), got 3"},
      {"0 1 2 3  1 2 3 4", "youngModulus=\"0\"",
       "[/root/fem youngModulus] expected values > 0, got 0"},
      {"0 1 2 3  1 2 3 4", "poissonRatio=\"0.5\"",
       "[/root/fem poissonRatio] expected -1 < poissonRatio < 0.5"},
      {"0 1 2 3  1 2 3 7", "",
       "[/root/fem topology] 1 tetrahedra use points out of range of the 5 points"},
      {"0 1 2 3  1 2 3 4", "method=\"corotational\"", "one of"},
  };
  for (const Case& c : cases) {
    bool loaded = true;
    const std::string messages =
        loadMessages(kTwoTetrahedraPoints, c.tetrahedra, c.attributes, loaded);
    EXPECT_FALSE(loaded) << c.attributes;
    EXPECT_NE(messages.find(c.needle), std::string::npos) << c.needle << " in:\n" << messages;
  }
}

TEST(TetrahedronFEMForceField, ReportsAMissingTopology) {
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString(
      "<Node name=\"root\"><MechanicalObject position=\"0 0 0  1 0 0  0 1 0  0 0 1\"/>"
      "<TetrahedronFEMForceField name=\"fem\"/></Node>"));
  const Message m = findError(scene.log(), "needs a topology with tetrahedra");
  EXPECT_EQ(m.field, "topology") << describe(scene.log());
}

}  // namespace
}  // namespace stroma::test
