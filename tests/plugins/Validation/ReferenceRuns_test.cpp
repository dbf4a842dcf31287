// SPDX-License-Identifier: MIT
// Convergence in mesh size against our own converged run (share/reference/
// CantileverSmallHexa.state, 80 x 8 x 8 linear hexahedra, made by make_references.sh): the
// coarse meshes' displacements interpolated at the reference's points, through
// ReferenceComparison's state-file reference located in the mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "plugins/SolidMechanics/FemTestScenes.h"

namespace stroma::test {
namespace {

const std::filesystem::path kReference =
    std::filesystem::path(STROMA_SOURCE_DIR) / "share/reference/CantileverSmallHexa.state";

/// RMS error over the reference's 6561 points, relative to the tip deflection 0.0403 m, of the
/// cantilever of CantileverSmallHexa.scn meshed with (10 k, k, k) cells of `elements`.
double errorAgainstReference(const std::string& elements, int k) {
  const FemMesh mesh = makeBoxMesh(Vec3d(1, 0.1, 0.1), Vec3i(10 * k, k, k));
  std::string clamped, tip;
  for (unsigned i = 0; i < mesh.points.size(); ++i) {
    if (mesh.points[i].x() < 1e-12) clamped += std::to_string(i) + " ";
    if (mesh.points[i].x() > 1 - 1e-12) tip += std::to_string(i) + " ";
  }
  const bool hexahedra = elements == "hexahedra";
  const std::string xml =
      "<Node name=\"root\" gravity=\"0 0 0\" dt=\"1\">\n<Node name=\"body\">\n"
      "<StaticSolver/><SparseLDLSolver/>"
      "<MeshTopology name=\"mesh\" " +
      elements + "=\"" +
      (hexahedra ? elementsText(mesh.hexahedra) : elementsText(mesh.tetrahedra)) +
      "\"/>\n"
      "<MechanicalObject name=\"dofs\" position=\"" +
      pointsText(mesh.points) + "\"/>\n<" +
      (hexahedra ? "HexahedronFEMForceField" : "TetrahedronFEMForceField") +
      " youngModulus=\"1e8\" poissonRatio=\"0.3\" method=\"small\"/>"
      "<FixedProjectiveConstraint indices=\"" +
      clamped +
      "\"/>"
      "<ConstantForceField indices=\"" +
      tip +
      "\" totalForce=\"0 0 -100\"/>"
      "<ReferenceComparison name=\"compare\" referenceState=\"" +
      kReference.string() + "\" referenceLength=\"0.0403\"/>\n</Node>\n</Node>\n";
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(scene, xml) || !scene.step(1)) return NAN;
  Base* compare = objectAt<Base>(scene, "/body/compare");
  return compare ? std::stod(compare->findData("rmsError")->valueText()) : NAN;
}

TEST(ReferenceRuns, LinearElementsConvergeToTheConvergedRun) {
  if (!std::filesystem::exists(kReference))
    GTEST_SKIP() << "no " << kReference << ": run share/reference/make_references.sh";
  // Measured (relative RMS over the reference's points, k = 1, 2, 4): hexahedra 0.167, 0.0564,
  // 0.0129, least-squares slope 1.85 (1.56 then 2.13 between successive meshes: reaching the
  // asymptotic 2 of linear elements); tetrahedra 0.375, 0.239, 0.100, slope 0.95 (0.65 then
  // 1.26: still pre-asymptotic, linear tetrahedra lock in bending at 1 to 4 elements across).
  // Against Timoshenko the hexahedra's slope is only 1.54 (ReferenceComparison_test): beam
  // theory is not the limit of the 3-D clamped solid. Asserted: hexahedra in [1.7, 2.2] with
  // the last ratio above 3.5; tetrahedra decreasing with a slope in [0.7, 1.2].
  std::vector<double> hexahedra, tetrahedra;
  for (int k : {1, 2, 4}) {
    hexahedra.push_back(errorAgainstReference("hexahedra", k));
    tetrahedra.push_back(errorAgainstReference("tetrahedra", k));
  }
  const double hexSlope = std::log2(hexahedra[0] / hexahedra[2]) / 2;
  EXPECT_NEAR(hexSlope, 1.95, 0.25) << hexahedra[0] << " " << hexahedra[1] << " " << hexahedra[2];
  EXPECT_GT(hexahedra[1] / hexahedra[2], 3.5);
  EXPECT_GT(tetrahedra[0], tetrahedra[1]);
  EXPECT_GT(tetrahedra[1], tetrahedra[2]);
  const double tetSlope = std::log2(tetrahedra[0] / tetrahedra[2]) / 2;
  EXPECT_NEAR(tetSlope, 0.95, 0.25)
      << tetrahedra[0] << " " << tetrahedra[1] << " " << tetrahedra[2];
}

}  // namespace
}  // namespace stroma::test
