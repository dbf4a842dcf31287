// SPDX-License-Identifier: MIT
// NonUniformHexahedronFEMForceFieldAndMass in scenes: without finer levels it is
// HexahedronFEMForceField with each cell weighted by its filled fraction; the force passes the
// force-field test (finite differences of f, assembled K) for large and polar; the total mass
// is density x filled volume; SOFA's NonUniformHexahedronFEMForceFieldAndMass.scn (less its
// collision components) runs; bad input.
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "HexahedronCondensation.h"
#include "plugins/MeshIO/SceneFixture.h"
#include "plugins/SolidMechanics/CorotationalBounds.h"
#include "plugins/SolidMechanics/FemTestScenes.h"
#include "plugins/SparseGrid/SurfaceMeshes.h"
#include "simulation/MechanicalOperations.h"
#include "support/ForceFieldTest.h"
#include "topology/MeshGeometry.h"

namespace stroma::test {
namespace {

/// The surface as SparseGridTopology attributes (position and triangles written inline).
std::string surfaceAttributes(const TriangleSurface& s) {
  std::string triangles;
  for (const Triangle& t : s.triangles)
    triangles +=
        std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + " ";
  return "position=\"" + pointsText(s.points) + "\" triangles=\"" + triangles + "\"";
}

/// A sphere of radius 1 in a sparse grid of n points per axis with `levels` finer levels, and
/// `component` after its MechanicalObject.
std::string sphereScene(int n, int levels, const std::string& component,
                        const std::string& rootAttributes = "gravity=\"0 0 0\" dt=\"0.01\"") {
  const std::string nText = std::to_string(n);
  return "<Node name=\"root\" " + rootAttributes + ">\n<Node name=\"body\">\n" +
         "<SparseGridTopology name=\"grid\" n=\"" + nText + " " + nText + " " + nText +
         "\" nbVirtualFinerLevels=\"" + std::to_string(levels) + "\" " +
         surfaceAttributes(icosphere(2)) + "/>\n<MechanicalObject name=\"dofs\"/>\n" + component +
         "\n</Node>\n</Node>\n";
}

std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> result;
  for (double v; in >> v;) result.push_back(v);
  return result;
}

std::string dataText(Scene& scene, const std::string& path, const std::string& field) {
  std::string why;
  Base* object = resolveObjectPath(scene.root(), path, why);
  EXPECT_NE(object, nullptr) << path << ": " << why;
  const BaseData* data = object ? object->findData(field) : nullptr;
  EXPECT_NE(data, nullptr) << path << "." << field;
  return data ? data->valueText() : "";
}

const Topology* gridOf(Scene& scene) {
  std::string why;
  return dynamic_cast<const Topology*>(resolveObjectPath(scene.root(), "/root/body/grid", why));
}

/// Sum of fraction x volume of the hexahedra of the grid of `scene`.
double filledVolume(Scene& scene) {
  const Topology* grid = gridOf(scene);
  const std::vector<double> fractions =
      numbers(dataText(scene, "/root/body/grid", "volumeFractions"));
  double volume = 0;
  for (std::size_t e = 0; e < fractions.size(); ++e)
    volume += fractions[e] * signedVolume(grid->positions(), grid->hexahedra()[e]);
  return volume;
}

TEST(NonUniformHexahedronFEMForceFieldAndMass,
     WithoutFinerLevelsIsHexahedronFemWeightedByFractions) {
  // nbVirtualFinerLevels = 0: each hexahedron is the full element of its cell times its filled
  // fraction, so K equals that of HexahedronFEMForceField given youngModulus = E x fraction per
  // hexahedron, and each point's lumped mass is sum fraction rho V / 8 over its cells.
  const double E = 1000, rho = 2;
  Runtime runtime;
  Scene nonUniform(runtime);
  ASSERT_TRUE(loadQuietly(nonUniform,
                          sphereScene(6, 0,
                                      "<NonUniformHexahedronFEMForceFieldAndMass name=\"fem\" "
                                      "youngModulus=\"1000\" poissonRatio=\"0.3\" density=\"2\" "
                                      "lumpedMass=\"true\"/>")));
  const std::vector<double> fractions =
      numbers(dataText(nonUniform, "/root/body/grid", "volumeFractions"));
  ASSERT_GT(fractions.size(), 50u);
  std::string weighted;
  for (double f : fractions) weighted += std::to_string(E * f) + " ";
  Runtime runtime2;
  Scene uniform(runtime2);
  ASSERT_TRUE(loadQuietly(uniform, sphereScene(6, 0,
                                               "<HexahedronFEMForceField youngModulus=\"" +
                                                   weighted + "\" poissonRatio=\"0.3\"/>")));
  // std::to_string keeps 6 decimals: E f to about 1e-9 relative.
  const Eigen::SparseMatrix<double> K1 = assembleStiffness(nonUniform),
                                    K2 = assembleStiffness(uniform);
  EXPECT_LT((K1 - K2).norm(), 1e-8 * K2.norm());
  const Topology* grid = gridOf(nonUniform);
  std::vector<double> expected(grid->nbPoints(), 0.0);
  for (std::size_t e = 0; e < fractions.size(); ++e) {
    const double cellMass =
        fractions[e] * rho * signedVolume(grid->positions(), grid->hexahedra()[e]);
    for (Index v : grid->hexahedra()[e]) expected[v] += cellMass / 8;
  }
  const std::vector<double> masses = numbers(dataText(nonUniform, "/root/body/fem", "vertexMass"));
  ASSERT_EQ(masses.size(), expected.size());
  for (std::size_t i = 0; i < masses.size(); ++i) EXPECT_NEAR(masses[i], expected[i], 1e-14) << i;
}

TEST(NonUniformHexahedronFEMForceFieldAndMass, ChildrenAreTheOctantsAtTheParentsCorners) {
  // The condensation takes child q of a cell (FinerLevel::parentsChildren) as the octant at the
  // cell's corner q, its corners interpolated trilinearly from the cell's (L_q). Check that
  // convention on the levels SparseGridTopology builds: every child's corners, as stored in the
  // finer grid, are X L_q^T.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, sphereScene(5, 2, "")));
  const Topology* grid = gridOf(scene);
  ASSERT_NE(grid, nullptr);
  const auto levels = grid->sparseGridFinerLevels();
  ASSERT_EQ(levels.size(), 2u);
  std::size_t checked = 0;
  for (std::size_t k = levels.size(); k-- > 0;) {
    const sparsegrid::SparseGrid& parents =
        k + 1 < levels.size() ? levels[k + 1].grid : *grid->sparseGrid();
    const sparsegrid::SparseGrid& children = levels[k].grid;
    ASSERT_EQ(levels[k].parentsChildren.size(), parents.hexahedra.size());
    for (std::size_t p = 0; p < parents.hexahedra.size(); ++p) {
      fem::HexahedronVectors X;
      for (int i = 0; i < 8; ++i) X.col(i) = parents.points[parents.hexahedra[p][i]];
      for (int q = 0; q < 8; ++q) {
        const Index c = levels[k].parentsChildren[p][q];
        if (c == kInvalidIndex) continue;
        const fem::HexahedronVectors expected = X * fem::computeChildInterpolation(q).transpose();
        for (int i = 0; i < 8; ++i)
          EXPECT_LT((children.points[children.hexahedra[c][i]] - expected.col(i)).norm(), 1e-12);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100u);
}

TEST(NonUniformHexahedronFEMForceFieldAndMass, MaterialChangesWhileRunningTakeEffectAtTheNextStep) {
  // K is linear in E and M in rho: doubling youngModulus doubles K, tripling density triples the
  // mass; a refused value (a modulus of 0) is a warning naming the field, and the previous
  // matrices stay.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(
      loadQuietly(scene, sphereScene(4, 1,
                                     "<NonUniformHexahedronFEMForceFieldAndMass name=\"fem\" "
                                     "nbVirtualFinerLevels=\"1\" youngModulus=\"1000\" "
                                     "density=\"10\"/>")));
  const Eigen::SparseMatrix<double> K1 = assembleStiffness(scene);
  const double m1 = numbers(dataText(scene, "/root/body/fem", "totalMass"))[0];
  std::string why;
  Base* fem = resolveObjectPath(scene.root(), "/root/body/fem", why);
  ASSERT_NE(fem, nullptr) << why;
  ASSERT_TRUE(fem->findData("youngModulus")->read("2000", why)) << why;
  ASSERT_TRUE(fem->findData("density")->read("30", why)) << why;
  const Eigen::SparseMatrix<double> K2 = assembleStiffness(scene);  // forces first: refreshed
  EXPECT_LT((K2 - 2 * K1).norm(), 1e-12 * K2.norm());
  EXPECT_NEAR(numbers(dataText(scene, "/root/body/fem", "totalMass"))[0], 3 * m1, 1e-12 * m1);
  ASSERT_TRUE(fem->findData("youngModulus")->read("0", why)) << why;
  const Eigen::SparseMatrix<double> K3 = assembleStiffness(scene);
  EXPECT_EQ(scene.log().errorCount(), 0u);
  bool warned = false;
  for (const Message& m : scene.log().messages())
    warned = warned || (m.level == MessageLevel::warning && m.field == "youngModulus" &&
                        m.text.find("not applied") != std::string::npos);
  EXPECT_TRUE(warned);
  EXPECT_LT((K3 - K2).norm(), 1e-14 * K2.norm());
}

class RotatingNonUniform : public ::testing::TestWithParam<const char*> {};

TEST_P(RotatingNonUniform, PassesTheForceFieldTestWithinTheCorotationalBounds) {
  // As HexahedronFEMForceField (tests/plugins/SolidMechanics): at strains of order p the
  // corotational f differs from -dE/dx, and the tangent R K R^T from df/dx, by O(p); the
  // assembled matrix equals the products, rigid motions give no force. Here with the stiffness
  // condensed from one finer level of a sphere's grid (boundary cells, empty children).
  const double p = 1e-3;
  const ForceFieldTestReport r = measureForceField(
      sphereScene(4, 1,
                  "<NonUniformHexahedronFEMForceFieldAndMass nbVirtualFinerLevels=\"1\" "
                  "youngModulus=\"1000\" poissonRatio=\"0.3\" density=\"10\" method=\"" +
                      std::string(GetParam()) + "\"/>"),
      {.rotationInvariant = true, .perturbation = p});
  ASSERT_TRUE(r.failure.empty()) << r.describe();
  std::printf("%s\n", r.describe().c_str());
  expectCorotationalBounds(r, p, /*exactEnergy=*/false);
}

INSTANTIATE_TEST_SUITE_P(NonUniformHexahedronFEMForceFieldAndMass, RotatingNonUniform,
                         ::testing::Values("large", "polar"),
                         [](const auto& info) { return std::string(info.param); });

TEST(NonUniformHexahedronFEMForceFieldAndMass, TotalMassIsDensityTimesFilledVolume) {
  // The condensation keeps the sum of the mass entries (the rows of L_c sum to 1), so the
  // total is rho x sum of the finest cells' fraction x volume; the topology's fractions are the
  // means of its finer cells', so that is rho x the grid's filled volume, at every level count.
  const double rho = 1070;
  const double sphere = icosphere(2).volume();
  for (int levels : {0, 1, 2}) {
    SCOPED_TRACE(levels);
    Runtime runtime;
    Scene scene(runtime);
    const std::string L = std::to_string(levels);
    ASSERT_TRUE(loadQuietly(scene, sphereScene(5, levels,
                                               "<NonUniformHexahedronFEMForceFieldAndMass "
                                               "name=\"fem\" nbVirtualFinerLevels=\"" +
                                                   L + "\" density=\"1070\" "
                                                       "minimumFraction=\"0\"/>")));
    const double total = numbers(dataText(scene, "/root/body/fem", "totalMass")).at(0);
    const double filled = filledVolume(scene);
    EXPECT_NEAR(total, rho * filled, 1e-12 * total);
    // And the grid measures the sphere's volume (SparseGrid README: well under 1 %).
    EXPECT_NEAR(filled, sphere, 0.01 * sphere);
    const std::vector<double> masses = numbers(dataText(scene, "/root/body/fem", "vertexMass"));
    double sum = 0;
    for (double m : masses) sum += m;
    EXPECT_NEAR(sum, total, 1e-12 * total);
  }
}

TEST(NonUniformHexahedronFEMForceFieldAndMass, FractionFloorLeavesNoPointWithoutMassOrStiffness) {
  // On the sphere in an 8^3 grid some boundary cells sample no material: with the measured
  // fractions alone, their points have neither mass nor stiffness and a direct solver meets a
  // zero pivot. The floor (minimumFraction, 1e-3 by default) gives them a little of both and
  // changes the total mass by at most rho x alpha x the volume of the floored cells.
  const auto lumped = [](Scene& scene) {
    return numbers(dataText(scene, "/root/body/fem", "vertexMass"));
  };
  const std::string fem =
      "<NonUniformHexahedronFEMForceFieldAndMass name=\"fem\" density=\"1000\" "
      "youngModulus=\"1e4\" ";
  Runtime runtime;
  Scene measured(runtime), floored(runtime);
  ASSERT_TRUE(loadQuietly(measured, sphereScene(8, 0, fem + "minimumFraction=\"0\"/>")));
  ASSERT_TRUE(loadQuietly(floored, sphereScene(8, 0, fem + "/>")));
  const std::vector<double> without = lumped(measured), with = lumped(floored);
  ASSERT_EQ(without.size(), with.size());
  const auto massless = std::count(without.begin(), without.end(), 0.0);
  EXPECT_GT(massless, 0) << "the case this floor is for no longer occurs on this grid";
  EXPECT_GT(*std::min_element(with.begin(), with.end()), 0.0);
  const Eigen::SparseMatrix<double> K = assembleStiffness(floored);
  for (int i = 0; i < K.rows(); ++i) EXPECT_LT(K.coeff(i, i), 0.0) << "dof " << i;
  const Topology* grid = gridOf(floored);
  const std::vector<double> fractions =
      numbers(dataText(floored, "/root/body/grid", "volumeFractions"));
  double added = 0;
  for (std::size_t e = 0; e < fractions.size(); ++e)
    added += std::max(0.0, 1e-3 - fractions[e]) * signedVolume(grid->positions(), grid->hexahedra()[e]);
  const auto total = [](const std::vector<double>& m) {
    double sum = 0;
    for (double v : m) sum += v;
    return sum;
  };
  EXPECT_NEAR(total(with) - total(without), 1000 * added, 1e-12 * total(with));
  // A direct solver now takes an implicit step of the body under gravity.
  Scene falling(runtime);
  ASSERT_TRUE(loadQuietly(falling, sphereScene(8, 0,
                                               "<EulerImplicitSolver/><SparseLDLSolver/>" +
                                                   fem + "/>",
                                               "gravity=\"0 -9.8 0\" dt=\"0.01\"")));
  EXPECT_TRUE(falling.step(0.01));
  EXPECT_EQ(falling.log().count(MessageLevel::error), 0u);
}

/// Total of the mass matrix of the bodies under `node` (sum of the entries of M, over 3).
double assembledMass(Scene& scene, const std::string& nodePath) {
  std::string why;
  Node* node = dynamic_cast<Node*>(resolveObjectPath(scene.root(), nodePath, why));
  EXPECT_NE(node, nullptr) << nodePath << ": " << why;
  if (!node) return 0;
  MechanicalOperations mop(*node, scene.timing());
  MechanicalParams mp;
  mp.kFactor = 0;
  mp.mFactor = 1;
  AssembledMatrix A;
  mop.assemble(mp, A);
  return Eigen::MatrixXd(A.matrix()).sum() / 3;
}

TEST(NonUniformHexahedronFEMForceFieldAndMass, SofasSceneWithoutItsCollisionComponents) {
  // SOFA's examples/Component/SolidMechanics/FEM/NonUniformHexahedronFEMForceFieldAndMass.scn:
  // two armadillos in SparseGridTopology n = 8 6 7, one with HexahedronFEMForceFieldAndMass,
  // one with this component condensed from 2 virtual finer levels, both falling under gravity.
  // The test copy leaves out the collision pipeline, the salad bowls and the Colli* nodes
  // (collision comes with a later issue). 100 steps, no NaN; the non-uniform armadillo weighs
  // density x its filled volume, the uniform one density x the volume of its full cells.
  const std::filesystem::path sofa = std::filesystem::path(STROMA_SHARED_DIR) / "sofa";
  const std::filesystem::path file =
      sofa / "examples/Component/SolidMechanics/FEM/NonUniformHexahedronFEMForceFieldAndMass.scn";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is absent";
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto erase = [&text](const std::string& start, const std::string& end) {
    const auto at = text.find(start);
    if (at == std::string::npos) return false;
    text.erase(at, text.find(end, at) + end.size() - at);
    return true;
  };
  for (const char* tag :
       {"<CollisionPipeline", "<BruteForceBroadPhase", "<BVHNarrowPhase",
        "<MinProximityIntersection", "<CollisionResponse", "<include", "<include"})
    ASSERT_TRUE(erase(tag, "/>")) << tag;
  for (const char* node : {"<Node name=\"Colliunif\"", "<Node name=\"Collinonunif\""})
    ASSERT_TRUE(erase(node, "</Node>")) << node;
  // The measured fractions as they are (no floor), for the exact mass identity below.
  const std::string tag = "<NonUniformHexahedronFEMForceFieldAndMass ";
  const auto component = text.find(tag);
  ASSERT_NE(component, std::string::npos);
  text.insert(component + tag.size(), "minimumFraction=\"0\" ");
  Runtime runtime;
  Scene scene(runtime);
  runtime.addDataDirectory(sofa / "share");
  ASSERT_TRUE(scene.loadString(text)) << [&] {
    std::string m;
    for (const Message& msg : scene.log().messages()) m += formatForConsole(msg) + "\n";
    return m;
  }();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u);
  const double rho = 10;
  std::string why;
  const auto* uniformGrid = dynamic_cast<const Topology*>(
      resolveObjectPath(scene.root(), "/SandBox/uniform/sparseGridTopology", why));
  ASSERT_NE(uniformGrid, nullptr) << why;
  double cellsVolume = 0;
  for (const Hexahedron& h : uniformGrid->hexahedra())
    cellsVolume += signedVolume(uniformGrid->positions(), h);
  const std::vector<double> fractions =
      numbers(dataText(scene, "/SandBox/non uniform/sparseGridTopology", "volumeFractions"));
  const auto* grid = dynamic_cast<const Topology*>(
      resolveObjectPath(scene.root(), "/SandBox/non uniform/sparseGridTopology", why));
  ASSERT_NE(grid, nullptr) << why;
  double filled = 0;
  for (std::size_t e = 0; e < fractions.size(); ++e)
    filled += fractions[e] * signedVolume(grid->positions(), grid->hexahedra()[e]);
  const double nonUniformMass = numbers(dataText(
      scene, "/SandBox/non uniform/nonUniformHexahedronFEMForceFieldAndMass", "totalMass"))[0];
  EXPECT_NEAR(nonUniformMass, rho * filled, 1e-12 * nonUniformMass);
  EXPECT_NEAR(assembledMass(scene, "/SandBox/non uniform"), nonUniformMass, 1e-10 * nonUniformMass);
  EXPECT_NEAR(assembledMass(scene, "/SandBox/uniform"), rho * cellsVolume,
              1e-10 * rho * cellsVolume);
  EXPECT_LT(filled, 0.8 * cellsVolume);  // the armadillo fills its boundary cells partly
  std::printf(
      "[ armadillo ] %zu / %zu hexahedra, mass uniform %.6g, non-uniform %.6g (filled %.1f %%)\n",
      uniformGrid->hexahedra().size(), fractions.size(), rho * cellsVolume, nonUniformMass,
      100 * filled / cellsVolume);

  const std::string dofs = "/SandBox/non uniform/mechanicalObject";
  const std::vector<double> rest = numbers(dataText(scene, dofs, "position"));
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene.step()) << i;
  EXPECT_EQ(scene.log().errorCount(), 0u);
  for (const std::string& path : {std::string("/SandBox/uniform/mechanicalObject"), dofs}) {
    const std::vector<double> x = numbers(dataText(scene, path, "position"));
    ASSERT_FALSE(x.empty()) << path;
    for (double v : x) ASSERT_TRUE(std::isfinite(v)) << path;
  }
  // Free fall for 6 s (dt 0.06): the centre of mass drops by g t^2 / 2 = 176.6 (no collision).
  const std::vector<double> x = numbers(dataText(scene, dofs, "position"));
  double drop = 0;
  for (std::size_t i = 2; i < x.size(); i += 3) drop += (rest[i] - x[i]) / double(x.size() / 3);
  EXPECT_NEAR(drop, 0.5 * 9.81 * 36, 0.05 * 0.5 * 9.81 * 36);
}

/// A sphere's grid of 9^3 cells (about 400 kept: the element loops split in tasks of 128)
/// (condensed from one finer level, consistent mass) hanging from 4 points under gravity, implicit
/// Euler and 25 CG iterations: positions after 3 steps.
std::vector<Vec3d> simulateSphere(int threads) {
  Runtime runtime;
  Scene scene(runtime);
  scene.setThreadCount(threads);
  if (!loadQuietly(
          scene, sphereScene(10, 1,
                             "<EulerImplicitSolver/><CGLinearSolver iterations=\"25\" "
                             "tolerance=\"1e-12\" threshold=\"1e-30\"/>"
                             "<NonUniformHexahedronFEMForceFieldAndMass nbVirtualFinerLevels=\"1\" "
                             "youngModulus=\"1e4\" poissonRatio=\"0.3\" density=\"100\" "
                             "method=\"polar\"/><FixedProjectiveConstraint indices=\"0 1 2 3\"/>",
                             "gravity=\"0 -9.81 0\" dt=\"0.01\"")))
    return {};
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(scene.step());
  const auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs");
  const auto x = dofs->readCoord(VecId::position()), rest = dofs->readCoord(VecId::restPosition());
  double fell = 0;  // the free points fall, the fixed ones stay
  for (std::size_t i = 0; i < x.size(); ++i) fell = std::max(fell, rest[i].y() - x[i].y());
  EXPECT_GT(fell, 1e-4);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(x[i], rest[i]);
  return std::vector<Vec3d>(x.begin(), x.end());
}

TEST(NonUniformHexahedronFEMForceFieldAndMass, SameResultsBitForBitWithOneOrTwoThreads) {
  // Element loops in parallel, each element writing its own corners, then per-vertex sums in
  // element order: the thread count does not change a bit.
  const std::vector<Vec3d> one = simulateSphere(1), two = simulateSphere(2);
  ASSERT_GT(one.size(), 300u);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(Vec3d)), 0);
  for (const Vec3d& p : one) ASSERT_TRUE(p.allFinite());
}

// --- Material from a volume image -------------------------------------------------------------

class ImageMaterial : public SceneFixture {
 protected:
  /// A MetaImage of 16 x 2 x 2 voxels of 0.5 covering [0, 8] x [0, 1] x [0, 1]: value 0 for
  /// x < 4, 255 beyond. Returns the header's path.
  std::string writeTwoMaterialImage(int firstStiffVoxel = 8) {
    std::string bytes;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 16; ++i) bytes += char(i < firstStiffVoxel ? 0 : 255);
    write("bar.raw", bytes);
    return write("bar.mhd",
                 "ObjectType = Image\nNDims = 3\nDimSize = 16 2 2\nElementSpacing = 0.5 0.5 0.5\n"
                 "Offset = 0.25 0.25 0.25\nElementType = MET_UCHAR\nElementDataFile = bar.raw\n");
  }
  /// A bar [0, 8] x [0, 1] x [0, 1] in 8 x 1 x 1 cells, the end x = 0 fixed, 4 N pulling the
  /// end x = 8 (1 N on each corner), statically solved; `material` is the component's material
  /// attributes.
  std::string barScene(const std::string& material, int levels = 0) {
    const std::string L = "nbVirtualFinerLevels=\"" + std::to_string(levels) + "\" ";
    return "<Node name=\"root\" gravity=\"0 0 0\" dt=\"1\">\n<Node name=\"body\">\n"
           "<StaticSolver newton_iterations=\"3\"/>\n<SparseLDLSolver/>\n"
           "<SparseGridTopology name=\"grid\" n=\"9 2 2\" min=\"0 0 0\" max=\"8 1 1\" " +
           L + surfaceAttributes(boxSurface(Vec3d::Zero(), Vec3d(8, 1, 1))) +
           "/>\n<MechanicalObject name=\"dofs\"/>\n"
           "<NonUniformHexahedronFEMForceFieldAndMass name=\"fem\" method=\"small\" "
           "poissonRatio=\"0\" " +
           L + material +
           "/>\n<FixedProjectiveConstraint indices=\"0 1 2 3\"/>\n"
           "<ConstantForceField indices=\"32 33 34 35\" force=\"1 0 0\"/>\n</Node>\n</Node>\n";
  }
};

TEST_F(ImageMaterial, TwoMaterialBarInTractionIsTwoSpringsInSeries) {
  // Poisson ratio 0: the trilinear cells of a bar one cell thick in uniform traction carry the
  // 1D field exactly (uniform strain per cell, no lateral stress), so each cell is a spring of
  // stiffness E_i phi_i A / h in series: u(x_k) = F sum_{i < k} h / (E_i phi_i A), phi_i the
  // cell's filled fraction (read from the grid). The image gives E = 1000 Pa to the half x < 4
  // (value 0) and 5000 Pa to the other (value 255); the density transfer 100 and 300 kg/m^3.
  const std::string image = writeTwoMaterialImage();
  // Without finer levels, and condensed from one level of 16 x 2 x 2 cells (one voxel each):
  // full children of one material condense exactly to the coarse element.
  for (int levels : {0, 1}) {
    SCOPED_TRACE(levels);
    ASSERT_TRUE(load(barScene("imageFile=\"" + image +
                                  "\" youngModulusTransfer=\"0 1000 255 5000\" "
                                  "densityTransfer=\"0 100 255 300\"",
                              levels)))
        << messages();
    EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
    const Topology* grid = topology("/root/body/grid");
    ASSERT_EQ(grid->hexahedra().size(), 8u);
    const std::vector<double> fractions = numbers(value("/root/body/grid", "volumeFractions"));
    const std::vector<double> rest = numbers(value("/root/body/dofs", "position"));
    ASSERT_EQ(rest.size(), 36u * 3);
    for (int p = 0; p < 4; ++p) {
      ASSERT_EQ(rest[3 * p], 0.0);
      ASSERT_EQ(rest[3 * (32 + p)], 8.0);
    }
    ASSERT_TRUE(scene.step()) << messages();
    const std::vector<double> x = numbers(value("/root/body/dofs", "position"));
    // Cells in x order: hexahedron e spans [x0, x0 + 1] where x0 is its lowest corner.
    std::vector<double> cellCompliance(8, 0.0);
    double expectedMass = 0;
    for (std::size_t e = 0; e < 8; ++e) {
      const Hexahedron& h = grid->hexahedra()[e];
      const int x0 = int(std::lround(grid->positions()[h[0]].x()));
      const double E = x0 < 4 ? 1000 : 5000, rho = x0 < 4 ? 100 : 300;
      cellCompliance[x0] = 1.0 / (E * fractions[e]);
      expectedMass += rho * fractions[e];
    }
    double maxError = 0, uEnd = 0;
    for (std::size_t p = 0; p < 36; ++p) {
      const int k = int(std::lround(rest[3 * p]));
      double u = 0;
      for (int i = 0; i < k; ++i) u += 4.0 * cellCompliance[i];
      maxError = std::max(maxError, std::abs(x[3 * p] - rest[3 * p] - u));
      maxError = std::max({maxError, std::abs(x[3 * p + 1] - rest[3 * p + 1]),
                           std::abs(x[3 * p + 2] - rest[3 * p + 2])});
      uEnd = std::max(uEnd, u);
    }
    std::printf("[ bar ] end displacement %.9g, largest error vs springs in series %.2e\n", uEnd,
                maxError);
    EXPECT_LT(maxError, 1e-10 * uEnd);
    // About 4 x (4 / 1000 + 4 / 5000) = 0.0192 with fractions near 1.
    EXPECT_NEAR(uEnd, 0.0192, 0.05 * 0.0192);
    EXPECT_NEAR(numbers(value("/root/body/fem", "totalMass"))[0], expectedMass,
                1e-12 * expectedMass);
  }
}

TEST_F(ImageMaterial, CellHoldingTwoMaterialsGetsTheirVolumeMeanUnderUniformStrain) {
  // The interface at x = 3.5, inside coarse cell [3, 4], condensed from one finer level (cells of
  // 0.5, one voxel each). The coarse trilinear field strains that cell uniformly, and with
  // nu = 0 its condensed stiffness in traction is then the volume mean of its children's
  // moduli (3000 Pa here; the Voigt bound, stiffer than the series 1667 Pa of the true 1D
  // field): u_end = F (3 / 1000 + 1 / 3000 + 4 / 5000), exactly. The same bar meshed at the
  // finest size gives the springs in series, F (3.5 / 1000 + 4.5 / 5000), 6 % more.
  const std::string image = writeTwoMaterialImage(7);
  ASSERT_TRUE(
      load(barScene("imageFile=\"" + image + "\" youngModulusTransfer=\"0 1000 255 5000\"", 1)))
      << messages();
  const std::vector<double> fractions = numbers(value("/root/body/grid", "volumeFractions"));
  for (double f : fractions) ASSERT_EQ(f, 1.0);
  ASSERT_TRUE(scene.step()) << messages();
  const std::vector<double> x = numbers(value("/root/body/dofs", "position"));
  double uEnd = 0;
  for (std::size_t p = 32; p < 36; ++p) uEnd += (x[3 * p] - 8.0) / 4;
  const double condensed = 4 * (3.0 / 1000 + 1.0 / 3000 + 4.0 / 5000);
  EXPECT_NEAR(uEnd, condensed, 1e-10 * condensed);
  const double series = 4 * (3.5 / 1000 + 4.5 / 5000);
  EXPECT_NEAR(uEnd / series, 0.9394, 1e-4);
}

TEST_F(ImageMaterial, NegativeModulusFromTheTransferIsAnErrorNamingTheValue) {
  const std::string image = writeTwoMaterialImage();
  EXPECT_FALSE(
      load(barScene("imageFile=\"" + image + "\" youngModulusTransfer=\"0 1000 255 -5\"")));
  const Message m = find(MessageLevel::error, "-5 at image value 255");
  EXPECT_EQ(m.field, "youngModulusTransfer");
  EXPECT_EQ(m.componentPath, "/root/body/fem");
  EXPECT_FALSE(load(barScene("imageFile=\"" + image + "\" densityTransfer=\"0 -1 255 10\"")));
  EXPECT_EQ(find(MessageLevel::error, "-1 at image value 0").field, "densityTransfer");
}

TEST_F(ImageMaterial, MissingImageIsAnErrorNamingTheField) {
  EXPECT_FALSE(load(barScene("imageFile=\"no/such/image.mhd\" youngModulusTransfer=\"0 1 1 2\"")));
  bool named = false;
  for (const Message& m : messagesAt(MessageLevel::error)) named = named || m.field == "imageFile";
  EXPECT_TRUE(named) << messages();
}

// --- Bad input -----------------------------------------------------------------------------

class BadInput : public SceneFixture {};

TEST_F(BadInput, NoSparseGridIsAnErrorNamingTheTopology) {
  EXPECT_FALSE(
      load("<Node name=\"root\">\n<RegularGridTopology name=\"grid\" n=\"3 3 3\" min=\"0 0 0\" "
           "max=\"1 1 1\"/>\n<MechanicalObject/>\n<NonUniformHexahedronFEMForceFieldAndMass "
           "name=\"fem\"/>\n</Node>\n"));
  const Message m = find(MessageLevel::error, "SparseGridTopology");
  EXPECT_EQ(m.field, "topology");
  EXPECT_EQ(m.componentPath, "/root/fem");
}

TEST_F(BadInput, MoreFinerLevelsThanTheGridKeepsIsAnError) {
  EXPECT_FALSE(load(sphereScene(4, 1,
                                "<NonUniformHexahedronFEMForceFieldAndMass name=\"fem\" "
                                "nbVirtualFinerLevels=\"2\"/>")));
  const Message m = find(MessageLevel::error, "keeps 1");
  EXPECT_EQ(m.field, "nbVirtualFinerLevels");
}

}  // namespace
}  // namespace stroma::test
