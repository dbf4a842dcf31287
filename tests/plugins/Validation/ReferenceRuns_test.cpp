// SPDX-License-Identifier: MIT
// Convergence in mesh size against fine reference runs: our own (share/reference/
// CantileverSmallHexa.state, 80 x 8 x 8 linear hexahedra, make_references.sh) and CalculiX's
// (share/reference/calculix, 80 x 8 x 8 C3D8I, cantilever_ccx.py): the coarse meshes'
// displacements interpolated at the reference's points, through ReferenceComparison's
// state-file reference located in the mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "ValidationScenes.h"

namespace stroma::test {
namespace {

const std::filesystem::path kReferenceDir =
    std::filesystem::path(STROMA_SOURCE_DIR) / "share/reference";
const std::filesystem::path kReference = kReferenceDir / "CantileverSmallHexa.state";
const std::filesystem::path kCalculix = kReferenceDir / "calculix/CantileverSmallCalculix.state";
const std::filesystem::path kCalculixLarge =
    kReferenceDir / "calculix/CantileverLargeCalculix.state";

/// RMS error over the 6561 points of `reference`, relative to the tip deflection 0.0403 m, of
/// the cantilever of CantileverSmallHexa.scn meshed with (10 k, k, k) cells of `elements`.
double errorAgainstReference(const std::filesystem::path& reference, const std::string& elements,
                             int k) {
  const std::string xml =
      cantileverScene(elements, k,
                      "<ReferenceComparison name=\"compare\" referenceState=\"" +
                          reference.string() + "\" referenceLength=\"0.0403\"/>");
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(scene, xml) || !scene.step(1)) return NAN;
  return comparisonOutput(scene, "rmsError");
}

/// Checks the errors against `reference` of linear hexahedra and tetrahedra at k = 1, 2, 4:
/// least-squares slopes of log error against log h within `tolerance` of the expected ones,
/// the hexahedra's last error ratio above `lastRatio`, the tetrahedra's errors decreasing.
void expectOrders(const std::filesystem::path& reference, double hexSlope, double lastRatio,
                  double tetSlope, double tolerance) {
  std::vector<double> hex, tet;
  for (int k : {1, 2, 4}) {
    hex.push_back(errorAgainstReference(reference, "hexahedra", k));
    tet.push_back(errorAgainstReference(reference, "tetrahedra", k));
  }
  EXPECT_NEAR(std::log2(hex[0] / hex[2]) / 2, hexSlope, tolerance)
      << hex[0] << " " << hex[1] << " " << hex[2];
  EXPECT_GT(hex[1] / hex[2], lastRatio);
  EXPECT_GT(tet[0], tet[1]);
  EXPECT_GT(tet[1], tet[2]);
  EXPECT_NEAR(std::log2(tet[0] / tet[2]) / 2, tetSlope, 0.25)
      << tet[0] << " " << tet[1] << " " << tet[2];
}

TEST(ReferenceRuns, LinearElementsConvergeToTheConvergedRun) {
  if (!std::filesystem::exists(kReference))
    GTEST_SKIP() << "no " << kReference << ": run share/reference/make_references.sh";
  // Measured (relative RMS over the reference's points, k = 1, 2, 4): hexahedra 0.167, 0.0564,
  // 0.0129, least-squares slope 1.85 (1.56 then 2.13 between successive meshes); tetrahedra
  // 0.375, 0.239, 0.100, slope 0.95 (0.65 then 1.26: still pre-asymptotic, linear tetrahedra
  // lock in bending at 1 to 4 elements across). Against Timoshenko the hexahedra's slope is
  // only 1.54 (ReferenceComparison_test): beam theory is not the limit of the 3-D clamped
  // solid. Asserted: hexahedra in [1.7, 2.2] with the last ratio above 3.5; tetrahedra
  // decreasing with a slope in [0.7, 1.2].
  expectOrders(kReference, 1.95, 3.5, 0.95, 0.25);
}

TEST(ReferenceRuns, LinearElementsConvergeToCalculix) {
  if (!std::filesystem::exists(kCalculix))
    GTEST_SKIP() << "no " << kCalculix << ": run share/reference/calculix/cantilever_ccx.py";
  // Measured: hexahedra 0.171, 0.0606, 0.0172 (slope 1.66; 1.50 then 1.82 between successive
  // meshes), tetrahedra 0.379, 0.243, 0.104 (0.93). Against CalculiX the hexahedra's order is
  // lower than against our own 80 x 8 x 8 run (1.85): that run shares their locking bias (its
  // tip is 0.9 % short of CalculiX's), so part of the coarse error cancels. Asserted: hexahedra
  // in [1.45, 1.89] with the last ratio above 3.2; tetrahedra decreasing, slope in [0.7, 1.2].
  expectOrders(kCalculix, 1.67, 3.2, 0.95, 0.22);
}

/// RMS error against CalculiX's large-deflection run (60 x 6 x 6 C3D8I, NLGEOM), relative to
/// its tip deflection 0.4955 m, of CantileverLargeHexa.scn's beam in (10 k, k, k) corotational
/// hexahedra, brought to equilibrium by 40 damped implicit Euler steps as there.
double largeDeflectionError(int k) {
  const std::string n =
      std::to_string(10 * k + 1) + " " + std::to_string(k + 1) + " " + std::to_string(k + 1);
  const std::string xml =
      "<Node name=\"root\" dt=\"0.1\" gravity=\"0 0 0\"><Node name=\"body\">"
      "<EulerImplicitSolver/><SparseLDLSolver/>"
      "<RegularGridTopology name=\"grid\" min=\"0 0 0\" max=\"1 0.1 0.1\" n=\"" +
      n +
      "\"/>"
      "<MechanicalObject name=\"dofs\" position=\"@grid.position\"/>"
      "<MeshMatrixMass massDensity=\"1000\"/>"
      "<HexahedronFEMForceField youngModulus=\"1e8\" poissonRatio=\"0.3\" method=\"large\"/>"
      "<BoxROI name=\"clamped\" box=\"-0.001 -0.01 -0.01 0.001 0.11 0.11\" "
      "position=\"@dofs.rest_position\"/>"
      "<FixedProjectiveConstraint indices=\"@clamped.indices\"/>"
      "<BoxROI name=\"tip\" box=\"0.999 -0.01 -0.01 1.001 0.11 0.11\" "
      "position=\"@dofs.rest_position\"/>"
      "<ConstantForceField indices=\"@tip.indices\" totalForce=\"0 0 -1666.6667\"/>"
      "<ReferenceComparison name=\"compare\" referenceState=\"" +
      kCalculixLarge.string() + "\" referenceLength=\"0.4955\"/></Node></Node>";
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(scene, xml)) return NAN;
  for (int step = 0; step < 40; ++step)
    if (!scene.step()) return NAN;
  return comparisonOutput(scene, "rmsError");
}

TEST(ReferenceRuns, CorotationalHexahedraConvergeToCalculixInLargeDeflection) {
  if (!std::filesystem::exists(kCalculixLarge))
    GTEST_SKIP() << "no " << kCalculixLarge << ": run share/reference/calculix/cantilever_ccx.py";
  // P L^2 / (E I) = 2. Measured RMS errors: 10 x 1 x 1 cells 0.148, 20 x 2 x 2 0.0491 (and, by
  // `stroma run`, 40 x 4 x 4 0.0144, 60 x 6 x 6 0.0072: share/reference/README.md). Asserted:
  // the two coarse values within 20 % and a ratio above 2.5.
  const double coarse = largeDeflectionError(1), fine = largeDeflectionError(2);
  EXPECT_NEAR(coarse, 0.148, 0.03);
  EXPECT_NEAR(fine, 0.0491, 0.01);
  EXPECT_GT(coarse / fine, 2.5);
}

}  // namespace
}  // namespace stroma::test
