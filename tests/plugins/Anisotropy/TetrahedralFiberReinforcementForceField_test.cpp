// SPDX-License-Identifier: MIT
// TetrahedralFiberReinforcementForceField: the generic force-field checks (fibers per object
// and per element), the energy of a uniform strain against the formula, no force for
// isotropic constants, rotating the fibers with the body, and bad input.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <random>
#include <sstream>

#include "AnisotropyTestScenes.h"
#include "plugins/TensorMass/TensorMassTestScenes.h"
#include "simulation/ForceField.h"
#include "support/ForceFieldTest.h"
#include "support/TestNames.h"
#include "topology/Topology.h"
#include "topology/TopologyChange.h"

namespace stroma::test {
namespace {

std::vector<Vec3d> randomDirections(std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<Vec3d> directions(count);
  for (Vec3d& a : directions) a = Vec3d(uniform(rng), uniform(rng), uniform(rng));
  return directions;
}

TEST(TetrahedralFiberReinforcementForceField, PassesTheForceFieldTestWithOneFiberDirection) {
  checkForceField(
      tensorMassScene(makeRandomTetrahedralMesh(), fiberField(kTissue, Vec3d(1, 2, 0.5))),
      {.hasEnergy = true, .rotationInvariant = false});
}

TEST(TetrahedralFiberReinforcementForceField, PassesTheForceFieldTestWithFibersPerElement) {
  const FemMesh mesh = makeRandomTetrahedralMesh();
  checkForceField(tensorMassScene(mesh, fiberField(kTissue, Vec3d::UnitX(),
                                                   randomDirections(mesh.tetrahedra.size(), 4))),
                  {.hasEnergy = true, .rotationInvariant = false});
}

TEST(TetrahedralFiberReinforcementForceField, PassesTheForceFieldTestBesideItsIsotropicPart) {
  // The whole transversely isotropic material, tested as a sum through the named field and
  // the system matrix; with Spencer's parameters this time.
  const anisotropy::SpencerParameters p = anisotropy::computeSpencerParameters(kTissue);
  const std::string fields =
      "<TetrahedralFiberReinforcementForceField name=\"fibers\" fiberDirection=\"0 1 1\" "
      "alpha=\"" +
      exact(p.alpha) + "\" beta=\"" + exact(p.beta) + "\" shearModulusL=\"" + exact(p.muL) +
      "\" shearModulusT=\"" + exact(p.muT) + "\"/><TetrahedronFEMForceField method=\"small\" " +
      isotropicPartText(kTissue) + "/>";
  checkForceField(tensorMassScene(makeRandomTetrahedralMesh(), fields),
                  {.forceField = "/root/body/fibers", .hasEnergy = true});
}

/// fiberField with method="polar".
std::string polarField(const Vec3d& direction, const std::vector<Vec3d>& directions = {}) {
  std::string field = fiberField(kTissue, direction, directions);
  return field.insert(field.size() - 2, " method=\"polar\"");
}

TEST(TetrahedralFiberReinforcementForceField, PolarPassesTheForceFieldTestRotationInvariant) {
  // Corotational: the exact gradient and Hessian of the energy, rotation included
  // (CorotationalReinforcement.h), so the default tolerances hold, with rigid motions too.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  for (bool perElement : {false, true}) {
    SCOPED_TRACE(perElement ? "per element" : "per object");
    const std::string field =
        perElement ? polarField(Vec3d::UnitX(), randomDirections(mesh.tetrahedra.size(), 12))
                   : polarField(Vec3d(1, 2, 0.5));
    const ForceFieldTestReport r = checkForceField(tensorMassScene(mesh, field),
                                                   {.hasEnergy = true, .rotationInvariant = true});
    std::printf("[ polar    ] %s", r.describe().c_str());
  }
}

TEST(TetrahedralFiberReinforcementForceField, PolarForcesTurnWithTheDeformedBody) {
  // Rest shape and fibers unchanged, the deformed body rotated by Q: forces Q f, same energy;
  // the small-strain method sees the rotation as a strain.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.02));
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(1.4, Vec3d(0.5, 1, -1).normalized()).toRotationMatrix();
  const std::string scene = tensorMassScene(mesh, polarField(Vec3d(1, 1, 0)));
  const Eigen::VectorXd f = forcesAt(scene, x);
  const Eigen::VectorXd g = forcesAt(scene, rotated(x, Q));
  Eigen::VectorXd expected(f.size());
  for (Eigen::Index i = 0; i < f.size(); i += 3) expected.segment<3>(i) = Q * f.segment<3>(i);
  EXPECT_LT(relativeDifference(g, expected), 1e-12);
  // At small displacements polar is the small-strain method, to first order.
  const std::vector<Vec3d> nearRest =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 1e-5));
  const Eigen::VectorXd linear =
      forcesAt(tensorMassScene(mesh, fiberField(kTissue, Vec3d(1, 1, 0))), nearRest);
  EXPECT_LT(relativeDifference(forcesAt(scene, nearRest), linear), 1e-3);
}

TEST(TetrahedralFiberReinforcementForceField, UniformStrainHasTheEnergyOfTheFormula) {
  // u = eps X: every tetrahedron has the strain eps, the energy is the mesh volume times
  // alpha (tr eps)(a.eps a) + 2 (mu_L - mu_T) a.eps^2 a + beta/2 (a.eps a)^2.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const Vec3d a = Vec3d(0.3, -1, 2).normalized();
  Eigen::Matrix3d eps;
  eps << 0.01, 0.004, -0.002, 0.004, -0.006, 0.003, -0.002, 0.003, 0.008;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, fiberField(kTissue, a))));
  std::vector<Vec3d> x = mesh.points;
  for (Vec3d& p : x) p += eps * p;
  setPositions(scene, x);
  const anisotropy::SpencerParameters p = anisotropy::computeSpencerParameters(kTissue);
  const double expected = meshVolume(mesh) * anisotropy::computeReinforcementEnergyDensity(
                                                 eps, a, p.alpha, p.beta, p.muL, p.muT);
  const double energy =
      objectAt<BaseForceField>(scene, "/root/body/fibers")->energy(MechanicalParams{});
  EXPECT_NEAR(energy, expected, 1e-12 * std::abs(expected));
  // A uniform stress: the forces on the interior points vanish.
}

TEST(TetrahedralFiberReinforcementForceField, IsotropicConstantsAddNoForce) {
  // E_L = E_T, nu_LT = nu_TT, G_LT = E / (2 (1 + nu)): alpha = beta = mu_L - mu_T = 0 to
  // round-off, and the isotropic part is (E, nu) itself.
  const double E = 3000, nu = 0.4;
  const anisotropy::EngineeringConstants iso{.youngModulusL = E,
                                             .youngModulusT = E,
                                             .poissonRatioLT = nu,
                                             .poissonRatioTT = nu,
                                             .shearModulusLT = E / (2 * (1 + nu))};
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDirections(mesh.points.size(), 8));  // up to 1 m: large
  const Eigen::VectorXd fibers = forcesAt(
      tensorMassScene(mesh,
                      fiberField(iso, Vec3d::UnitX(), randomDirections(mesh.tetrahedra.size(), 2))),
      x);
  const Eigen::VectorXd isotropic =
      forcesAt(tensorMassScene(mesh,
                               "<TetrahedronFEMForceField method=\"small\" youngModulus=\"3000\" "
                               "poissonRatio=\"0.4\"/>"),
               x);
  ASSERT_EQ(fibers.size(), isotropic.size());
  EXPECT_LT(fibers.norm(), 1e-13 * isotropic.norm());
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, fiberField(iso, Vec3d::UnitZ()))));
  auto* field = objectAt<Base>(scene, "/root/body/fibers");
  EXPECT_NEAR(std::stod(field->findData("isotropicYoungModulus")->valueText()), E, 1e-9 * E);
  EXPECT_NEAR(std::stod(field->findData("isotropicPoissonRatio")->valueText()), nu, 1e-12);
}

TEST(TetrahedralFiberReinforcementForceField, RotatingFibersAndBodyTogetherRotatesTheForces) {
  // Body, displacements and fibers rotated by Q: the forces are Q f and the energy is the same
  // (a material frame property of the law, per object and per element).
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.9, Vec3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.02));
  FemMesh turned = mesh;
  turned.points = rotated(mesh.points, Q);
  const std::vector<Vec3d> perElement = randomDirections(mesh.tetrahedra.size(), 6);
  std::vector<Vec3d> perElementTurned = perElement;
  for (Vec3d& a : perElementTurned) a = Q * a;
  const Vec3d a(0.2, 1, -0.4);
  for (bool perObject : {true, false}) {
    SCOPED_TRACE(perObject ? "per object" : "per element");
    const std::string before =
        perObject ? fiberField(kTissue, a) : fiberField(kTissue, a, perElement);
    const std::string after =
        perObject ? fiberField(kTissue, Q * a) : fiberField(kTissue, a, perElementTurned);
    const Eigen::VectorXd f = forcesAt(tensorMassScene(mesh, before), x);
    const Eigen::VectorXd g = forcesAt(tensorMassScene(turned, after), rotated(x, Q));
    ASSERT_EQ(f.size(), g.size());
    Eigen::VectorXd expected(f.size());
    for (Eigen::Index i = 0; i < f.size(); i += 3) expected.segment<3>(i) = Q * f.segment<3>(i);
    EXPECT_LT(relativeDifference(g, expected), 1e-12);
    // Not the same as turning the body alone: the fibers matter.
    const Eigen::VectorXd h = forcesAt(tensorMassScene(turned, before), rotated(x, Q));
    EXPECT_GT(relativeDifference(h, expected), 0.05);
  }
}

TEST(TetrahedralFiberReinforcementForceField, ChangesWhileRunningTakeEffectAtTheNextStep) {
  // Fibers along x then y: the forces change, and are those of a fresh field along y.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.02));
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, fiberField(kTissue, Vec3d::UnitX()))));
  setPositions(scene, x);
  auto* field = objectAt<Base>(scene, "/root/body/fibers");
  std::string error;
  ASSERT_TRUE(field->findData("fiberDirection")->read("0 2 0", error)) << error;
  const Eigen::VectorXd alongY =
      forcesAt(tensorMassScene(mesh, fiberField(kTissue, Vec3d::UnitY())), x);
  EXPECT_LT(relativeDifference(computeForces(scene), alongY), 1e-14);
  // An invalid change is a warning naming the field; the previous fibers stay.
  ASSERT_TRUE(field->findData("fiberDirection")->read("0 0 0", error)) << error;
  EXPECT_LT(relativeDifference(computeForces(scene), alongY), 1e-14);
  bool warned = false;
  for (const Message& m : scene.log().messages())
    warned |= m.level == MessageLevel::warning && m.field == "fiberDirection";
  EXPECT_TRUE(warned) << describe(scene.log());
}

TEST(TetrahedralFiberReinforcementForceField, WarnsWhenTheIsotropicFieldBesideDoesNotMatch) {
  const FemMesh mesh = makeRandomTetrahedralMesh();
  for (const char* isotropic :
       {"<TetrahedralTensorMassForceField youngModulus=\"5000\" poissonRatio=\"0.3\"/>",
        "<TetrahedronFEMForceField method=\"large\" youngModulus=\"4566.98\" "
        "poissonRatio=\"0.324425\"/>"}) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(
        scene.loadString(tensorMassScene(mesh, fiberField(kTissue, Vec3d::UnitX()) + isotropic)));
    EXPECT_EQ(scene.log().count(MessageLevel::warning), 1u) << describe(scene.log());
    EXPECT_EQ(scene.log().errorCount(), 0u) << describe(scene.log());
  }
  // Linked to the outputs: no warning.
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_TRUE(loadQuietly(
      scene, tensorMassScene(mesh, fiberField(kTissue, Vec3d::UnitX()) +
                                       "<TetrahedralTensorMassForceField "
                                       "youngModulus=\"@fibers.isotropicYoungModulus\" "
                                       "poissonRatio=\"@fibers.isotropicPoissonRatio\"/>")));
}

TEST(TetrahedralFiberReinforcementForceField, SpencerParametersAreCheckedAgainstThePartner) {
  // Spencer's parameters do not give lambda: the partner's does. Its shear modulus must be
  // shearModulusT (else a warning), and the sum positive definite (else an error).
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::string partner =
      "<TetrahedronFEMForceField method=\"small\" youngModulus=\"3000\" poissonRatio=\"0.4\"/>";
  auto load = [&](const std::string& spencer, Scene& scene) {
    return scene.loadString(tensorMassScene(
        mesh,
        "<TetrahedralFiberReinforcementForceField name=\"fibers\" " + spencer + "/>" + partner));
  };
  auto has = [](Scene& scene, MessageLevel level, const char* field, const char* text) {
    for (const Message& m : scene.log().messages())
      if (m.level == level && m.field == field && m.text.find(text) != std::string::npos)
        return true;
    return false;
  };
  {
    Runtime runtime;
    Scene scene(runtime);
    // mu_T = 3000 / 2.8 = 1071.43 Pa; a beta of -1e5 Pa makes the fiber direction unstable.
    EXPECT_FALSE(load("alpha=\"0\" beta=\"-1e5\" shearModulusL=\"2000\" "
                      "shearModulusT=\"1071.4285714285713\"",
                      scene) &&
                 scene.log().errorCount() == 0);
    EXPECT_TRUE(has(scene, MessageLevel::error, "beta", "not positive definite"))
        << describe(scene.log());
    scene.step();
  }
  {
    Runtime runtime;
    Scene scene(runtime);
    EXPECT_TRUE(
        load("alpha=\"100\" beta=\"1000\" shearModulusL=\"2000\" shearModulusT=\"900\"", scene));
    EXPECT_EQ(scene.log().errorCount(), 0u) << describe(scene.log());
    EXPECT_TRUE(has(scene, MessageLevel::warning, "shearModulusT", "1071.43"))
        << describe(scene.log());
  }
}

TEST(TetrahedralFiberReinforcementForceField, FollowsTheRemovalOfTetrahedra) {
  // Cutting: after Topology::removeTetrahedra, the forces are those of a fresh field on the
  // remaining tetrahedra (in the topology's new order) with their fibers, and fiberDirections
  // has followed the renumbering; for both methods.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::vector<Vec3d> fibers = randomDirections(mesh.tetrahedra.size(), 21);
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.02));
  const std::vector<Index> cut{3, 40, 41, 70};
  for (const char* method : {"small", "polar"}) {
    SCOPED_TRACE(method);
    std::string field = fiberField(kTissue, Vec3d::UnitX(), fibers);
    field.insert(field.size() - 2, std::string(" method=\"") + method + "\"");
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, field)));
    setPositions(scene, x);
    computeForces(scene);  // built before the cut
    auto* topology = objectAt<Topology>(scene, "/root/body/mesh");
    std::string error;
    ASSERT_TRUE(topology->removeTetrahedra(cut, error)) << error;
    const Eigen::VectorXd after = computeForces(scene);

    // The same renumbering on the mesh and the fibers, then a fresh scene.
    FemMesh remaining = mesh;
    std::vector<Vec3d> remainingFibers = fibers;
    std::vector<Index> removed = cut;
    std::sort(removed.rbegin(), removed.rend());
    applyRemoval(remaining.tetrahedra, removed);
    applyRemoval(remainingFibers, removed);
    ASSERT_EQ(topology->tetrahedra().size(), remaining.tetrahedra.size());
    for (std::size_t t = 0; t < remaining.tetrahedra.size(); ++t)
      for (int i = 0; i < 4; ++i)
        ASSERT_EQ(topology->tetrahedra()[t][i], remaining.tetrahedra[t][i]);
    std::string fresh = fiberField(kTissue, Vec3d::UnitX(), remainingFibers);
    fresh.insert(fresh.size() - 2, std::string(" method=\"") + method + "\"");
    EXPECT_LT(relativeDifference(after, forcesAt(tensorMassScene(remaining, fresh), x)), 1e-13);
    // fiberDirections, printed exactly (shortest round-trip form), is the renumbered list.
    std::istringstream printed(
        objectAt<Base>(scene, "/root/body/fibers")->findData("fiberDirections")->valueText());
    std::vector<Vec3d> directions;
    Vec3d a;
    while (printed >> a.x() >> a.y() >> a.z()) directions.push_back(a);
    EXPECT_EQ(directions, remainingFibers);
    // (The topology warns that a corner point lost its last tetrahedron; the field says nothing.)
    for (const Message& m : scene.log().messages())
      EXPECT_FALSE(m.level >= MessageLevel::warning && m.componentPath == "/root/body/fibers")
          << formatForConsole(m);
  }
}

TEST(TetrahedralFiberReinforcementForceField, OneAndThreeThreadsGiveTheSameBits) {
  // 1728 tetrahedra: several tasks of kGrain elements; forces and tangent of both methods.
  const FemMesh mesh = makeBoxMesh(Vec3d(0.8, 0.6, 0.6), Vec3i(8, 6, 6));
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.02));
  const std::vector<Vec3d> fibers = randomDirections(mesh.tetrahedra.size(), 5);
  for (const char* method : {"small", "polar"}) {
    SCOPED_TRACE(method);
    std::string field = fiberField(kTissue, Vec3d::UnitX(), fibers);
    field.insert(field.size() - 2, std::string(" method=\"") + method + "\"");
    Eigen::VectorXd forces[2];
    Eigen::SparseMatrix<double> stiffness[2];
    const int threads[2] = {1, 3};
    for (int k = 0; k < 2; ++k) {
      Runtime runtime;
      Scene scene(runtime);
      scene.setThreadCount(threads[k]);
      ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, field)));
      setPositions(scene, x);
      forces[k] = computeForces(scene);
      stiffness[k] = assembleStiffness(scene);
    }
    EXPECT_TRUE(forces[0] == forces[1]);
    EXPECT_EQ((stiffness[0] - stiffness[1]).norm(), 0.0);
    EXPECT_GT(forces[0].norm(), 0.0);
  }
}

// --- Bad input -----------------------------------------------------------------------------

struct BadInput {
  const char* what;
  std::string attributes;  // of the force field
  const char* field;       // the field the error names
  const char* text;        // part of the error
};
void PrintTo(const BadInput& c, std::ostream* out) { *out << c.what; }

const std::string kConstants = constantsText(kTissue);

std::string withConstants(const std::string& changed) {
  // kTissue with one attribute replaced (or added).
  std::string text = kConstants;
  const std::string name = changed.substr(0, changed.find('='));
  const std::size_t at = text.find(name + "=");
  if (at == std::string::npos) return text + " " + changed;
  const std::size_t end = text.find('"', text.find('"', at) + 1);
  return text.substr(0, at) + changed + text.substr(end + 1);
}

class FiberReinforcementBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(FiberReinforcementBadInput, IsAnErrorNamingTheComponentAndField) {
  const BadInput& c = GetParam();
  const FemMesh mesh = makeRandomTetrahedralMesh();  // 72 tetrahedra
  Runtime runtime;
  Scene scene(runtime);
  const bool loaded = scene.loadString(tensorMassScene(
      mesh, "<TetrahedralFiberReinforcementForceField name=\"fibers\" " + c.attributes + "/>"));
  EXPECT_FALSE(loaded && scene.log().errorCount() == 0) << describe(scene.log());
  bool found = false;
  for (const Message& m : errors(scene.log()))
    found |=
        m.field == c.field && m.text.find(c.text) != std::string::npos &&
        formatForConsole(m).find("/root/body/fibers (TetrahedralFiberReinforcementForceField)") !=
            std::string::npos;
  EXPECT_TRUE(found) << c.what << ":\n" << describe(scene.log());
  scene.step();  // no crash when asked to step anyway
}

INSTANTIATE_TEST_SUITE_P(
    TetrahedralFiberReinforcementForceField, FiberReinforcementBadInput,
    ::testing::Values(
        BadInput{"zero fiber direction", kConstants + " fiberDirection=\"0 0 0\"", "fiberDirection",
                 "non-zero"},
        BadInput{"wrong per-element count", kConstants + " fiberDirections=\"1 0 0  0 1 0  0 0 1\"",
                 "fiberDirections", "got 3 directions for the 72 tetrahedra"},
        BadInput{"nu_TT = 1", withConstants("poissonRatioTT=\"1\""), "poissonRatioTT",
                 "-1 < poissonRatioTT < 1"},
        BadInput{"compliance not positive definite", withConstants("poissonRatioLT=\"1.3\""),
                 "poissonRatioLT", "not positive definite"},
        BadInput{"zero E_L", withConstants("youngModulusL=\"0\""), "youngModulusL", "> 0"},
        BadInput{"negative G_LT", withConstants("shearModulusLT=\"-4000\""), "shearModulusLT",
                 "> 0"},
        BadInput{"isotropic part without bulk modulus", withConstants("poissonRatioTT=\"-0.6\""),
                 "poissonRatioTT", "bulk modulus"},
        BadInput{"a missing constant",
                 "youngModulusL=\"3e4\" youngModulusT=\"5e3\" "
                 "poissonRatioLT=\"0.35\" shearModulusLT=\"4e3\"",
                 "poissonRatioTT", "all five"},
        BadInput{"no material", "", "youngModulusL", "no material"},
        BadInput{"both kinds of parameters", kConstants + " alpha=\"100\"", "alpha", "not both"},
        BadInput{"Spencer without mu_T", "alpha=\"1\" beta=\"2\" shearModulusL=\"3\"",
                 "shearModulusT", "all four"}),
    NameFromWhat());

}  // namespace
}  // namespace stroma::test
