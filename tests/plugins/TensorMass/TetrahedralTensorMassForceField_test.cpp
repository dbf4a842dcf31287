// SPDX-License-Identifier: MIT
// TetrahedralTensorMassForceField: the same forces as the linear FEM tetrahedron, the generic
// force-field checks, what a rigid rotation does to the linear model, the tensors' structure,
// SOFA's example scene, run-time material changes and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "TensorMass/kernels/LinearTensorMass.h"
#include "TensorMassTestScenes.h"
#include "simulation/ForceField.h"
#include "support/ForceFieldTest.h"
#include "support/TestNames.h"
#include "topology/MeshAdjacency.h"

namespace stroma::test {
namespace {

constexpr double kYoungModulus = 3000, kPoissonRatio = 0.4;

std::string tensorMassField(const std::string& extra = "") {
  return "<TetrahedralTensorMassForceField name=\"tensorMass\" youngModulus=\"3000\" "
         "poissonRatio=\"0.4\" " +
         extra + "/>";
}

const std::string kSmallFem =
    "<TetrahedronFEMForceField name=\"fem\" method=\"small\" youngModulus=\"3000\" "
    "poissonRatio=\"0.4\"/>";

TEST(TetrahedralTensorMassForceField, ForcesEqualTheLinearFemTetrahedron) {
  // Seed 000 eq. 1.12 sums, per vertex and edge, the blocks of the element matrices that
  // TetrahedronFEMForceField (method small) applies element by element: the same forces up to
  // the order of the sums, on a mesh of irregular tetrahedra and random displacements of up to
  // 30 % of the spacing.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  ASSERT_GT(meshVolume(mesh), 0);
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::vector<Vec3d> x =
        displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.03, seed));
    const Eigen::VectorXd tensorMass = forcesAt(tensorMassScene(mesh, tensorMassField()), x);
    const Eigen::VectorXd fem = forcesAt(tensorMassScene(mesh, kSmallFem), x);
    EXPECT_LT(relativeDifference(tensorMass, fem), 1e-12) << "seed " << seed;
  }
}

TEST(TetrahedralTensorMassForceField, PassesTheForceFieldTest) {
  // Linear: f = -K U is exactly -dE/dx, K exact and symmetric; not rotation invariant.
  checkForceField(tensorMassScene(makeRandomTetrahedralMesh(), tensorMassField()),
                  {.hasEnergy = true, .rotationInvariant = false});
}

TEST(TetrahedralTensorMassForceField, ARotationBy90DegreesIsSeenAsAStrainOfMinusOne) {
  // Seed 004 section 2.2: the linear model is not rotation invariant. A rotation R by 90
  // degrees about z gives U = (R - I) X, whose linearized strain sym(R - I) = diag(-1, -1, 0)
  // is uniform: the energy is that of a 100 % compression in x and y,
  // W = V (lambda/2 (tr e)^2 + mu e:e) = V (2 lambda + 2 mu), and the forces are those of the
  // stress -2 (lambda + mu) on x and y faces, as large as the material's moduli.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, tensorMassField())));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 2, Vec3d::UnitZ()).toRotationMatrix();
  setPositions(scene, rotated(mesh.points, R));
  const auto* field = objectAt<BaseForceField>(scene, "/root/body/tensorMass");
  const fem::LameParameters lame = fem::computeLameParameters(kYoungModulus, kPoissonRatio);
  const double expected = meshVolume(mesh) * (2 * lame.lambda + 2 * lame.mu);
  const double energy = field->energy(MechanicalParams{});
  EXPECT_NEAR(energy, expected, 1e-10 * expected);
  // The net force is zero (the stress is uniform), the force on the boundary points is not:
  // the traction 2 (lambda + mu) (here 8.57 kPa) on faces of 0.01 to 0.02 m^2 gives tens of N.
  const Eigen::VectorXd f = computeForces(scene);
  double largest = 0;
  for (Eigen::Index i = 0; i < f.size(); i += 3)
    largest = std::max(largest, f.segment<3>(i).norm());
  EXPECT_GT(largest, 10.0);
  std::printf(
      "[ linear   ] 90-degree rotation: energy %.6g J (V (2 lambda + 2 mu) = %.6g J), "
      "largest force %.4g N\n",
      energy, expected, largest);
}

TEST(LinearTensorMass, StoresOneTensorPerVertexAndEdge) {
  // The kernel the component runs (LinearTensorMass.h), on the mesh's own edge list.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  std::vector<Tetrahedron> tetrahedra(mesh.tetrahedra.begin(), mesh.tetrahedra.end());
  std::vector<fem::TetrahedronShape> shapes(tetrahedra.size());
  for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
    fem::TetrahedronVectors rest;
    for (int i = 0; i < 4; ++i) rest.col(i) = mesh.points[tetrahedra[t][i]];
    ASSERT_EQ(fem::computeTetrahedronShape(rest, shapes[t]), fem::ElementStatus::ok);
  }
  const ElementEdges<6> edges = computeTetrahedronEdges(tetrahedra);
  tensormass::TensorMassMesh tensorMassMesh{.pointCount = mesh.points.size(),
                                            .tetrahedra = tetrahedra,
                                            .shapes = shapes,
                                            .edges = edges.edges,
                                            .edgesInTetrahedron = edges.edgesInElement,
                                            .triangles = {},
                                            .trianglesInTetrahedron = {}};
  tensormass::VertexEdgeTensors tensors;
  tensormass::buildLinearTensorMass(
      tensorMassMesh, fem::computeLameParameters(kYoungModulus, kPoissonRatio), tensors);
  EXPECT_EQ(tensors.vertexTensors.size(), mesh.points.size());
  EXPECT_EQ(tensors.edges, edges.edges);
  // K^pp is symmetric; every row of blocks sums to zero (translations cost nothing).
  std::vector<Eigen::Matrix3d> rowSums = tensors.vertexTensors;
  for (std::size_t e = 0; e < tensors.edges.size(); ++e) {
    rowSums[tensors.edges[e][0]] += tensors.edgeTensors[e];
    rowSums[tensors.edges[e][1]] += tensors.edgeTensors[e].transpose();
  }
  for (std::size_t p = 0; p < mesh.points.size(); ++p) {
    const double scale = tensors.vertexTensors[p].norm();
    EXPECT_LT((tensors.vertexTensors[p] - tensors.vertexTensors[p].transpose()).norm(),
              1e-13 * scale);
    EXPECT_LT(rowSums[p].norm(), 1e-12 * scale) << "point " << p;
  }
}

TEST(TetrahedralTensorMassForceField, RunsSofasExampleSceneUnmodified) {
  const std::filesystem::path sofa = std::filesystem::path(STROMA_SHARED_DIR) / "sofa";
  const std::filesystem::path file =
      sofa / "examples/Component/SolidMechanics/TensorMass/TetrahedralTensorMassForceField.scn";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is absent";
  Runtime runtime;
  runtime.addDataDirectory(sofa / "share");
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadFile(file)) << describe(scene.log());
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene.step()) << describe(scene.log());
  EXPECT_EQ(scene.log().errorCount(), 0u) << describe(scene.log());
  // Gravity bends the beam, fixed at z = 0: its free end (z = 19) has come down.
  const auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "/root/DoFs");
  const auto& x = dofs->readCoord(VecId::position());
  const auto& rest = dofs->readCoord(VecId::restPosition());
  double sag = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (rest[i].z() > 18.9) sag = std::max(sag, rest[i].y() - x[i].y());
  EXPECT_GT(sag, 0.1);
}

TEST(TetrahedralTensorMassForceField, MaterialChangesTakeEffectAtTheNextStep) {
  // Linear in E: doubling youngModulus doubles the forces.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.01));
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, tensorMassField())));
  setPositions(scene, x);
  const Eigen::VectorXd before = computeForces(scene);
  auto* field = objectAt<Base>(scene, "/root/body/tensorMass");
  std::string error;
  ASSERT_TRUE(field->findData("youngModulus")->read("6000", error)) << error;
  EXPECT_LT(relativeDifference(computeForces(scene), 2 * before), 1e-13);
  // An invalid value is a warning naming the field, and the previous material stays.
  ASSERT_TRUE(field->findData("poissonRatio")->read("0.5", error)) << error;
  EXPECT_LT(relativeDifference(computeForces(scene), 2 * before), 1e-13);
  bool warned = false;
  for (const Message& m : scene.log().messages())
    warned |= m.level == MessageLevel::warning && m.field == "poissonRatio";
  EXPECT_TRUE(warned) << describe(scene.log());
}

// --- Bad input -----------------------------------------------------------------------------

struct BadInput {
  const char* what;
  std::string attributes;  // of the force field
  bool flatten;            // make tetrahedron 0 flat
  bool invert;             // swap two vertices of tetrahedron 0
  const char* field;       // the field the error names
  const char* text;        // part of the error
};
void PrintTo(const BadInput& c, std::ostream* out) { *out << c.what; }

class TensorMassBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(TensorMassBadInput, IsAnErrorNamingTheComponentAndField) {
  const BadInput& c = GetParam();
  FemMesh mesh = makeRandomTetrahedralMesh();
  if (c.invert) std::swap(mesh.tetrahedra[0][2], mesh.tetrahedra[0][3]);
  if (c.flatten) {
    // Point 1 of tetrahedron 0 onto the plane of points 0, 2, 3... and 0's other
    // tetrahedra with it: take a fresh, isolated, flat tetrahedron instead.
    const unsigned n = static_cast<unsigned>(mesh.points.size());
    mesh.points.push_back(Vec3d(1, 1, 1));
    mesh.points.push_back(Vec3d(2, 1, 1));
    mesh.points.push_back(Vec3d(1, 2, 1));
    mesh.points.push_back(Vec3d(2, 2, 1));
    mesh.tetrahedra.push_back({n, n + 1, n + 2, n + 3});
  }
  for (const char* component :
       {"TetrahedralTensorMassForceField", "TetrahedralStVKTensorMassForceField"}) {
    SCOPED_TRACE(component);
    Runtime runtime;
    Scene scene(runtime);
    const std::string xml = tensorMassScene(
        mesh, std::string("<") + component + " name=\"field\" " + c.attributes + "/>");
    const bool loaded = scene.loadString(xml);
    EXPECT_FALSE(loaded && scene.log().errorCount() == 0) << describe(scene.log());
    bool found = false;
    for (const Message& m : errors(scene.log()))
      found |= m.field == c.field && m.text.find(c.text) != std::string::npos &&
               formatForConsole(m).find("field") != std::string::npos;
    EXPECT_TRUE(found) << c.what << ":\n" << describe(scene.log());
    // No crash when asked to step anyway.
    scene.step();
  }
}

INSTANTIATE_TEST_SUITE_P(
    TetrahedralTensorMassForceField, TensorMassBadInput,
    ::testing::Values(BadInput{"Poisson ratio 0.5", "youngModulus=\"1000\" poissonRatio=\"0.5\"",
                               false, false, "poissonRatio", "-1 < poissonRatio < 0.5"},
                      BadInput{"Poisson ratio 0.7", "youngModulus=\"1000\" poissonRatio=\"0.7\"",
                               false, false, "poissonRatio", "0.5"},
                      BadInput{"Poisson ratio -1", "youngModulus=\"1000\" poissonRatio=\"-1\"",
                               false, false, "poissonRatio", "-1 < poissonRatio < 0.5"},
                      BadInput{"negative Young's modulus",
                               "youngModulus=\"-5\" poissonRatio=\"0.3\"", false, false,
                               "youngModulus", "0"},
                      BadInput{"zero Young's modulus", "youngModulus=\"0\" poissonRatio=\"0.3\"",
                               false, false, "youngModulus", "> 0"},
                      BadInput{"flat tetrahedron", "", true, false, "topology", "flat"},
                      BadInput{"inverted tetrahedron", "", false, true, "topology", "inverted"}),
    NameFromWhat());

}  // namespace
}  // namespace stroma::test
