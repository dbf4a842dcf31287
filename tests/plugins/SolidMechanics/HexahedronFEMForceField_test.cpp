// SPDX-License-Identifier: MIT
// HexahedronFEMForceField and HexahedronFEMForceFieldAndMass: the generic force-field checks
// for each rotation method (with the documented bounds where the corotational force or tangent
// is not exact), MacNeal and Harder's patch test, the mass, and bad input.
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

/// 2 x 2 x 2 hexahedra of the unit cube, the interior point moved.
FemMesh smallHexahedralMesh() {
  FemMesh mesh = makeBoxMesh(Vec3d(1, 1, 1), Vec3i(2, 2, 2));
  distortInterior(mesh, Vec3d(1, 1, 1), 0.5, 0.15);
  return mesh;
}

std::string hexaScene(const std::string& component, const std::string& attributes) {
  return femScene(smallHexahedralMesh(), "hexahedra",
                  "<" + component + " name=\"fem\" youngModulus=\"1000\" poissonRatio=\"0.3\" " +
                      attributes + "/>");
}

// --- Generic force-field checks ------------------------------------------------------------

TEST(HexahedronFEMForceField, SmallIsLinearElasticityExactly) {
  checkForceField(hexaScene("HexahedronFEMForceField", "method=\"small\""),
                  {.hasEnergy = true, .rotationInvariant = false});
}

class RotatingHexahedra : public ::testing::TestWithParam<const char*> {};

TEST_P(RotatingHexahedra, PassTheForceFieldTestWithinTheCorotationalBounds) {
  // At strains of order p, for hexahedra with any rotation, f differs from -dE/dx and the
  // tangent from the Jacobian by O(p) (CorotationalElement.h; kernels README). Measured at
  // p = 1e-3 on this mesh: energy error 4.0e-5 (large), 7.4e-6 (polar, svd); addDForce error
  // 5.3e-4 (large), 3.8e-4 (polar, svd); net moment 7.6e-5 (large), 5.0e-6 (polar, svd);
  // everything else below 1e-12.
  const double p = 1e-3;
  const ForceFieldTestReport r = measureForceField(
      hexaScene("HexahedronFEMForceField", "method=\"" + std::string(GetParam()) + "\""),
      {.rotationInvariant = true, .perturbation = p});
  ASSERT_TRUE(r.failure.empty()) << r.describe();
  expectCorotationalBounds(r, p, /*exactEnergy=*/false);
}

INSTANTIATE_TEST_SUITE_P(HexahedronFEMForceField, RotatingHexahedra,
                         ::testing::Values("large", "polar", "svd"),
                         [](const auto& info) { return std::string(info.param); });

TEST(HexahedronFEMForceFieldAndMass, PassesTheForceFieldTest) {
  // Without gravity its force is the elastic one: the field under test is the mass.
  const ForceFieldTestReport r = measureForceField(
      hexaScene("HexahedronFEMForceFieldAndMass", "method=\"small\" density=\"1000\""),
      {.rotationInvariant = false});
  ASSERT_TRUE(r.failure.empty()) << r.describe();
  EXPECT_LT(r.energyError, 1e-6) << r.describe();
  EXPECT_LT(r.dForceError, 1e-6) << r.describe();
  EXPECT_LT(r.fieldMatrixError, 1e-12) << r.describe();
  EXPECT_LT(r.systemMatrixError, 1e-12) << r.describe();
  EXPECT_LT(r.restForce, 1e-12) << r.describe();
}

// --- Patch test (REFERENCES.md, MacNeal and Harder) ------------------------------------------

Vec3d patchDisplacement(const Vec3d& x) {
  Eigen::Matrix3d A;
  A << 2, 1, 1, 1, 2, 1, 1, 1, 2;
  return 0.5e-3 * A * x;
}

std::string patchScene(const std::string& method) {
  return femScene(makeMacNealHarderPatch(), "hexahedra",
                  "<HexahedronFEMForceField youngModulus=\"1e6\" poissonRatio=\"0.25\" "
                  "method=\"" +
                      method + "\"/>");
}

TEST(HexahedronFEMForceField, PassesTheMacNealHarderPatchTest) {
  // The 8 corners displaced by the linear field; the 8 interior points solved for.
  const FemMesh mesh = makeMacNealHarderPatch();
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, patchScene("small")));
  const Eigen::MatrixXd K(assembleStiffness(scene));
  Eigen::VectorXd uB(24), exactI(24);
  for (int i = 0; i < 8; ++i) {
    uB.segment<3>(3 * i) = patchDisplacement(mesh.points[i]);
    exactI.segment<3>(3 * i) = patchDisplacement(mesh.points[8 + i]);
  }
  // Points 0-7 are rows 0-23, points 8-15 rows 24-47.
  const Eigen::MatrixXd KII = K.bottomRightCorner(24, 24), KIB = K.bottomLeftCorner(24, 24);
  const Eigen::VectorXd uI = KII.ldlt().solve(-KIB * uB);
  EXPECT_LT((uI - exactI).norm() / exactI.norm(), 1e-10);
}

TEST(HexahedronFEMForceField, PolarAndSvdPassThePatchTestRotatedInEquilibrium) {
  // F is constant under a linear field, so the centre rotation of polar and svd is exactly
  // the applied one: the interior points are in equilibrium to round-off.
  const FemMesh mesh = makeMacNealHarderPatch();
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(1.1, Vec3d(-1, 2, 0.5).normalized()).toRotationMatrix();
  for (const char* method : {"polar", "svd"}) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, patchScene(method)));
    auto& x =
        objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs")->writeCoord(VecId::position());
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = Q * (mesh.points[i] + patchDisplacement(mesh.points[i]));
    const Eigen::VectorXd f = computeForces(scene);
    EXPECT_LT(f.tail(24).norm() / f.head(24).norm(), 1e-10) << method;
  }
}

// --- Mass ------------------------------------------------------------------------------------

TEST(HexahedronFEMForceFieldAndMass, MassIsDensityTimesVolumeConsistentOrLumped) {
  // A 2 x 1 x 1 m box of 4 x 2 x 2 hexahedra, density 500: 1000 kg. Gravity g: the force is
  // m_i g at each point; a uniform velocity v has kinetic energy 1/2 m |v|^2, and the
  // assembled M equals the matrix-free product, for both masses.
  const FemMesh mesh = makeBoxMesh(Vec3d(2, 1, 1), Vec3i(4, 2, 2));
  for (const char* lumped : {"false", "true"}) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(
        scene, femScene(mesh, "hexahedra",
                        std::string("<HexahedronFEMForceFieldAndMass name=\"fem\" density=\"500\" "
                                    "youngModulus=\"1e4\" method=\"large\" lumpedMass=\"") +
                            lumped + "\"/>",
                        "gravity=\"0 0 -10\"")));
    const Eigen::VectorXd f = computeForces(scene);
    EXPECT_NEAR(f.sum(), -10 * 1000, 1e-9) << lumped;
    // Corner points carry 1/8 of a hexahedron's mass: 1000 / 16 / 8 kg.
    EXPECT_NEAR(f[2], -10 * 1000.0 / 16 / 8, 1e-10) << lumped;

    MechanicalOperations mop(scene.root(), scene.timing());
    const VecId v = VecId::velocity(), out = mop.allocDeriv();
    auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs");
    for (Vec3d& vi : dofs->writeDeriv(v)) vi = Vec3d(1, -2, 2);
    EXPECT_NEAR(mop.kineticEnergy(), 0.5 * 1000 * 9, 1e-9) << lumped;

    MechanicalParams mass;
    mass.mFactor = 1;
    mass.kFactor = 0;
    Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(3 * mesh.points.size(), -1, 1);
    const VecId dx = mop.allocDeriv();
    mop.scatter(u, dx);
    mop.computeMBKdx(mass, out, dx);
    Eigen::VectorXd Mu;
    mop.gather(out, Mu);
    AssembledMatrix M;
    mop.assemble(mass, M);
    EXPECT_LT((M.matrix() * u - Mu).norm(), 1e-12 * Mu.norm()) << lumped;
    EXPECT_NEAR(M.matrix().sum(), 3 * 1000, 1e-9) << lumped;
  }
}

TEST(HexahedronFEMForceFieldAndMass, FallsFreelyWithTheConsistentMass) {
  // M (1 (x) g) is the gravity force and K annihilates translations: one implicit Euler step
  // from rest gives every point the velocity g dt.
  const FemMesh mesh = makeBoxMesh(Vec3d(2, 1, 1), Vec3i(4, 2, 2));
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(
      scene, femScene(mesh, "hexahedra",
                      "<EulerImplicitSolver/><CGLinearSolver iterations=\"200\" "
                      "tolerance=\"1e-14\" threshold=\"1e-30\"/>"
                      "<HexahedronFEMForceFieldAndMass density=\"500\" youngModulus=\"1e4\"/>",
                      "gravity=\"0 0 -10\" dt=\"0.01\"")));
  ASSERT_TRUE(scene.step());
  for (const Vec3d& v :
       objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs")->readDeriv(VecId::velocity()))
    EXPECT_LT((v - Vec3d(0, 0, -0.1)).norm(), 1e-12);
}

// --- Bad input -----------------------------------------------------------------------------

TEST(HexahedronFEMForceField, ReportsDegenerateRestHexahedraByIndex) {
  // Hexahedron 1 has its top face on its bottom face.
  const std::string points =
      "0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1  0 0 0  1 0 0  1 1 0  0 1 0";
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString(
      "<Node name=\"root\"><MeshTopology hexahedra=\"0 1 2 3 4 5 6 7  0 1 2 3 8 9 10 11\"/>"
      "<MechanicalObject position=\"" +
      points +
      "\"/>"
      "<HexahedronFEMForceField name=\"fem\"/></Node>"));
  const Message m = findError(scene.log(), "degenerate in the rest shape");
  EXPECT_EQ(m.componentPath, "/root/fem") << describe(scene.log());
  EXPECT_NE(m.text.find("elements 1"), std::string::npos) << m.text;
}

}  // namespace
}  // namespace stroma::test
