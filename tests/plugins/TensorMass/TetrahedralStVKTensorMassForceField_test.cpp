// SPDX-License-Identifier: MIT
// TetrahedralStVKTensorMassForceField and StandardTetrahedralFEMForceField: the tensor-mass
// form of St Venant-Kirchhoff gives the forces of the element-by-element one, both pass the
// generic force-field checks with their exact tangent, are rotation invariant where the
// linear model is not, and report bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "TensorMassTestScenes.h"
#include "simulation/ForceField.h"
#include "support/ForceFieldTest.h"
#include "support/TestNames.h"

namespace stroma::test {
namespace {

const std::string kMaterial = "youngModulus=\"3000\" poissonRatio=\"0.4\"";

std::string stvkTensorMass() {
  return "<TetrahedralStVKTensorMassForceField name=\"stvk\" " + kMaterial + "/>";
}
std::string standardFem(const std::string& material, const std::string& parameters = kMaterial) {
  return "<StandardTetrahedralFEMForceField name=\"fem\" materialName=\"" + material + "\" " +
         parameters + "/>";
}
std::string linearTensorMass() {
  return "<TetrahedralTensorMassForceField name=\"linear\" " + kMaterial + "/>";
}

TEST(TetrahedralStVKTensorMassForceField, ForcesEqualTheElementByElementStVK) {
  // Seed 004 eq. 15 regroups the terms of eq. 13 on vertices, edges, triangles and
  // tetrahedra: the same polynomial as P = F S element by element. Displacements of up to
  // 30 % of the spacing (strains of tens of %), where the cubic and quartic terms count.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  for (double amplitude : {0.001, 0.03}) {
    for (unsigned seed : {1u, 2u, 3u}) {
      const std::vector<Vec3d> x =
          displaced(mesh.points, randomDisplacements(mesh.points.size(), amplitude, seed));
      const Eigen::VectorXd tensorMass = forcesAt(tensorMassScene(mesh, stvkTensorMass()), x);
      const Eigen::VectorXd fem =
          forcesAt(tensorMassScene(mesh, standardFem("StVenantKirchhoff")), x);
      EXPECT_LT(relativeDifference(tensorMass, fem), 1e-12)
          << "amplitude " << amplitude << ", seed " << seed;
      // And the non-linear terms matter at 30 %: the linear model differs by much more.
      if (amplitude > 0.01) {
        const Eigen::VectorXd linear = forcesAt(tensorMassScene(mesh, linearTensorMass()), x);
        EXPECT_GT(relativeDifference(linear, fem), 0.05);
      }
    }
  }
}

TEST(TetrahedralStVKTensorMassForceField, EnergyEqualsTheElementByElementStVK) {
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.03));
  double energies[2];
  int i = 0;
  for (const std::string& field : {stvkTensorMass(), standardFem("StVenantKirchhoff")}) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, field)));
    setPositions(scene, x);
    const char* path = i == 0 ? "/root/body/stvk" : "/root/body/fem";
    energies[i++] = objectAt<BaseForceField>(scene, path)->energy(MechanicalParams{});
  }
  EXPECT_NEAR(energies[0], energies[1], 1e-12 * energies[1]);
}

TEST(TetrahedralStVKTensorMassForceField, PassesTheForceFieldTestWithItsExactTangent) {
  // f = -dW/dx, addDForce and the assembled matrix from the exact Hessian, symmetric; zero
  // force under rigid motions (the Green strain is rotation invariant).
  const ForceFieldTestReport r =
      checkForceField(tensorMassScene(makeRandomTetrahedralMesh(), stvkTensorMass()),
                      {.rotationInvariant = true, .perturbation = 0.2});
  std::printf("%s", r.describe().c_str());
}

TEST(StandardTetrahedralFEMForceField, PassesTheForceFieldTestForEachMaterial) {
  for (const char* material : {"StVenantKirchhoff", "NeoHookean"}) {
    SCOPED_TRACE(material);
    checkForceField(tensorMassScene(makeRandomTetrahedralMesh(), standardFem(material)),
                    {.rotationInvariant = true, .perturbation = 0.2});
  }
}

TEST(TetrahedralStVKTensorMassForceField, ARotationBy90DegreesGivesNoForce) {
  // Seed 004 section 3: St Venant-Kirchhoff is invariant under rotations. The linear model
  // sees the same rotation as a 100 % compression (TetrahedralTensorMassForceField_test):
  // the forces here are below 1e-12 of its.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(M_PI / 2, Vec3d::UnitZ())).toRotationMatrix();
  const std::vector<Vec3d> x = rotated(mesh.points, R);
  const Eigen::VectorXd linear = forcesAt(tensorMassScene(mesh, linearTensorMass()), x);
  const double linearScale = linear.norm();
  ASSERT_GT(linearScale, 10.0);
  for (const std::string& field :
       {stvkTensorMass(), standardFem("StVenantKirchhoff"), standardFem("NeoHookean")}) {
    SCOPED_TRACE(field);
    const Eigen::VectorXd f = forcesAt(tensorMassScene(mesh, field), x);
    EXPECT_LT(f.norm(), 1e-12 * linearScale);
  }
}

TEST(StandardTetrahedralFEMForceField, ReadsSofasParameterSetAsMuLambda) {
  // SOFA's example writes ParameterSet="3448.2759 31034.483": mu and lambda of E = 10000,
  // nu = 0.45. The same forces as youngModulus and poissonRatio.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.02));
  for (const char* material : {"StVenantKirchhoff", "NeoHookean"}) {
    const fem::LameParameters lame = fem::computeLameParameters(10000, 0.45);
    char parameters[96];
    std::snprintf(parameters, sizeof parameters, "ParameterSet=\"%.17g %.17g\"", lame.mu,
                  lame.lambda);
    const Eigen::VectorXd a = forcesAt(tensorMassScene(mesh, standardFem(material, parameters)), x);
    const Eigen::VectorXd b =
        forcesAt(tensorMassScene(
                     mesh, standardFem(material, "youngModulus=\"10000\" poissonRatio=\"0.45\"")),
                 x);
    EXPECT_LT(relativeDifference(a, b), 1e-14) << material;
  }
}

TEST(StandardTetrahedralFEMForceField, NeoHookeanAndStVKAgreeForSmallStrains) {
  // Both are linear elasticity with the same lambda and mu to first order in the strain.
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 1e-6));
  const Eigen::VectorXd stvk = forcesAt(tensorMassScene(mesh, standardFem("StVenantKirchhoff")), x);
  const Eigen::VectorXd neoHookean = forcesAt(tensorMassScene(mesh, standardFem("NeoHookean")), x);
  EXPECT_LT(relativeDifference(neoHookean, stvk), 1e-4);
}

TEST(StandardTetrahedralFEMForceField, NeoHookeanInvertedWhileRunningWarnsOnceAndGivesNoForce) {
  // det F <= 0: the neo-Hookean energy is not defined. The element is left out, with one
  // warning naming it and the time; StVK (defined everywhere) still pushes it back.
  FemMesh mesh;
  mesh.points = {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}, {0, 0, 0.1}};
  mesh.tetrahedra = {{0, 1, 2, 3}};
  std::vector<Vec3d> x = mesh.points;
  x[3].z() = -0.05;  // through the opposite face
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, tensorMassScene(mesh, standardFem("NeoHookean"))));
  setPositions(scene, x);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(computeForces(scene).norm(), 0);
  int warnings = 0;
  for (const Message& m : scene.log().messages())
    warnings += m.level == MessageLevel::warning &&
                m.text.find("tetrahedron 0 is inverted") != std::string::npos;
  EXPECT_EQ(warnings, 1) << describe(scene.log());
  EXPECT_GT(forcesAt(tensorMassScene(mesh, standardFem("StVenantKirchhoff")), x).norm(), 0);
}

// --- Bad input -----------------------------------------------------------------------------

struct BadMaterial {
  const char* what;
  std::string field;  // XML of the force field
  const char* name;   // the field the error names
  const char* text;   // part of the error
};
void PrintTo(const BadMaterial& c, std::ostream* out) { *out << c.what; }

class HyperelasticBadInput : public ::testing::TestWithParam<BadMaterial> {};

TEST_P(HyperelasticBadInput, IsAnErrorNamingTheComponentAndField) {
  const BadMaterial& c = GetParam();
  Runtime runtime;
  Scene scene(runtime);
  const bool loaded = scene.loadString(tensorMassScene(makeRandomTetrahedralMesh(), c.field));
  EXPECT_FALSE(loaded && scene.log().errorCount() == 0) << describe(scene.log());
  bool found = false;
  for (const Message& m : errors(scene.log()))
    found |= m.field == c.name && m.text.find(c.text) != std::string::npos;
  EXPECT_TRUE(found) << c.what << ":\n" << describe(scene.log());
  scene.step();  // no crash
}

INSTANTIATE_TEST_SUITE_P(
    StandardTetrahedralFEMForceField, HyperelasticBadInput,
    ::testing::Values(
        BadMaterial{
            "SOFA's default material",
            "<StandardTetrahedralFEMForceField youngModulus=\"1000\" poissonRatio=\"0.3\"/>",
            "materialName", "ArrudaBoyce is not implemented"},
        BadMaterial{"an unknown material", standardFem("Rubber"), "materialName",
                    "StVenantKirchhoff"},
        BadMaterial{"three parameters", standardFem("StVenantKirchhoff", "ParameterSet=\"1 2 3\""),
                    "ParameterSet", "expected 2 values"},
        BadMaterial{"negative mu", standardFem("NeoHookean", "ParameterSet=\"-1 2\""),
                    "ParameterSet", "mu > 0"},
        BadMaterial{"both ways",
                    standardFem("NeoHookean", "ParameterSet=\"1 2\" youngModulus=\"3\""),
                    "ParameterSet", "not both"},
        BadMaterial{"Poisson ratio 0.5", standardFem("NeoHookean", "poissonRatio=\"0.5\""),
                    "poissonRatio", "-1 < poissonRatio < 0.5"},
        BadMaterial{"StVK tensor-mass, Poisson ratio 0.5",
                    "<TetrahedralStVKTensorMassForceField poissonRatio=\"0.5\"/>", "poissonRatio",
                    "-1 < poissonRatio < 0.5"},
        BadMaterial{"StVK tensor-mass, zero Young's modulus",
                    "<TetrahedralStVKTensorMassForceField youngModulus=\"0\"/>", "youngModulus",
                    "> 0"}),
    NameFromWhat());

}  // namespace
}  // namespace stroma::test
