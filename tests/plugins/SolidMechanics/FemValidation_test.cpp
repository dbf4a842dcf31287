// SPDX-License-Identifier: MIT
// Validation of the FEM force fields against reference solutions (REFERENCES.md), and their
// determinism across thread counts.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "FemTestScenes.h"

namespace stroma::test {
namespace {

// --- Cantilever beam (REFERENCES.md, "Small-deflection cantilever") -------------------------
// L = 1 m, section 0.1 x 0.1 m, E = 1e8 Pa, nu = 0.3, tip load P = 100 N: Euler-Bernoulli
// 0.040000 m plus Timoshenko's shear term 3.06e-4 m (kappa = 0.8497).
constexpr double kLength = 1.0, kSide = 0.1, kLoad = 100.0;
constexpr double kTimoshenko = 0.040306;

/// Tip deflection (mean over the tip face, along -z) of the beam meshed with (10 k, k, k)
/// cells, by a static linear solve: the points at x = 0 clamped, P spread evenly on the points
/// at x = L, (-K) u = f_ext solved with a sparse LDL^T.
double cantileverDeflection(const std::string& elements, int k) {
  const FemMesh mesh = makeBoxMesh(Vec3d(kLength, kSide, kSide), Vec3i(10 * k, k, k));
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(scene, femScene(mesh, elements,
                                   std::string("<") +
                                       (elements == "hexahedra" ? "HexahedronFEMForceField"
                                                                : "TetrahedronFEMForceField") +
                                       " youngModulus=\"1e8\" poissonRatio=\"0.3\" "
                                       "method=\"small\"/>")))
    return NAN;
  const Eigen::SparseMatrix<double> K = assembleStiffness(scene);
  // Free degrees of freedom: those of the points with x > 0.
  const auto n = static_cast<Eigen::Index>(mesh.points.size());
  std::vector<Eigen::Index> freeIndex(3 * n, -1);
  Eigen::Index freeCount = 0;
  std::vector<Eigen::Index> tip;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (mesh.points[i].x() > 1e-12)
      for (int c = 0; c < 3; ++c) freeIndex[3 * i + c] = freeCount++;
    if (mesh.points[i].x() > kLength - 1e-12) tip.push_back(i);
  }
  const Eigen::SparseMatrix<double> A = restrictNegated(K, freeIndex, freeCount);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(freeCount);
  for (Eigen::Index i : tip) load[freeIndex[3 * i + 2]] = -kLoad / static_cast<double>(tip.size());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  EXPECT_EQ(solver.info(), Eigen::Success);
  const Eigen::VectorXd u = solver.solve(load);
  double deflection = 0;
  for (Eigen::Index i : tip) deflection -= u[freeIndex[3 * i + 2]];
  return deflection / static_cast<double>(tip.size());
}

/// Checks the relative deviation of each resolution (k = 1, 2, 4, 8) from Timoshenko's value
/// against its tolerance, and that it shrinks by at least `minimumRate` per refinement;
/// returns the ratios deflection / reference.
std::vector<double> checkConvergence(const std::string& elements, const double (&tolerance)[4],
                                     double minimumRate) {
  std::vector<double> ratios;
  for (int level = 0; level < 4; ++level) {
    const int k = 1 << level;
    ratios.push_back(cantileverDeflection(elements, k) / kTimoshenko);
    const double deviation = std::abs(1 - ratios.back());
    EXPECT_LT(deviation, tolerance[level]) << elements << ", k = " << k;
    if (level > 0) {
      EXPECT_GT(std::abs(1 - ratios[level - 1]) / deviation, minimumRate)
          << elements << ", k = " << k;
    }
  }
  return ratios;
}

TEST(FemValidation, TetrahedralCantileverConvergesToTimoshenko) {
  // Linear tetrahedra are far too stiff in bending on coarse meshes (shear locking); the
  // deviation shrinks with h, towards second order. Measured deflection / reference:
  // k = 1: 0.2194, 2: 0.5038, 4: 0.7873, 8: 0.9297 (deviation rates 1.6, 2.3, 3.0).
  // Tolerances on the deviation: 0.79, 0.50, 0.22, 0.075; rate > 1.5.
  checkConvergence("tetrahedra", {0.79, 0.50, 0.22, 0.075}, 1.5);
}

TEST(FemValidation, HexahedralCantileverConvergesToTimoshenko) {
  // Fully integrated trilinear hexahedra lock less. Measured deflection / reference:
  // k = 1: 0.6429, 2: 0.8692, 4: 0.9576, 8: 0.9836 (deviation rates 2.7, 3.1, 2.6).
  // Tolerances on the deviation: 0.36, 0.135, 0.045, 0.02; rate > 2.
  const std::vector<double> r = checkConvergence("hexahedra", {0.36, 0.135, 0.045, 0.02}, 2.0);
  // Richardson extrapolation of the two finest (second order): 0.9923. The remaining
  // difference is the 3D clamp (no Poisson contraction at x = 0) and the end load, which the
  // beam theory does not model: within 1 %.
  EXPECT_NEAR(r[3] + (r[3] - r[2]) / 3, 1.0, 0.01);
}

// --- Determinism across thread counts --------------------------------------------------------

/// A clamped beam of 48 x 6 x 6 cells falling under gravity, implicit Euler and 25 CG
/// iterations: positions after `steps` steps with `threads` threads.
std::vector<Vec3d> simulateBeam(const std::string& elements, const std::string& method, int threads,
                                int steps) {
  const FemMesh mesh = makeBoxMesh(Vec3d(4.8, 0.6, 0.6), Vec3i(48, 6, 6));
  std::string fixed;
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    if (mesh.points[i].x() == 0) fixed += std::to_string(i) + ' ';
  const std::string field =
      elements == "hexahedra" ? "HexahedronFEMForceField" : "TetrahedronFEMForceField";
  const std::string components =
      "<EulerImplicitSolver rayleighStiffness=\"0.1\" rayleighMass=\"0.1\"/>"
      "<CGLinearSolver iterations=\"25\" tolerance=\"1e-12\" threshold=\"1e-30\"/>"
      "<UniformMass totalMass=\"100\"/>"
      "<" +
      field + " name=\"fem\" youngModulus=\"1e5\" poissonRatio=\"0.4\" method=\"" + method +
      "\"/><FixedConstraint indices=\"" + fixed + "\"/>";
  Runtime runtime;
  Scene scene(runtime);
  scene.setThreadCount(threads);
  if (!loadQuietly(scene,
                   femScene(mesh, elements, components, "gravity=\"0 -9.81 0\" dt=\"0.01\"")))
    return {};
  for (int i = 0; i < steps; ++i) EXPECT_TRUE(scene.step());
  return objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs")->readCoord(VecId::position());
}

bool bitwiseEqual(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3d)) == 0;
}

TEST(FemValidation, OneAndTwoThreadsGiveTheSameBits) {
  // 10368 tetrahedra (2401 points) or 1728 hexahedra: several tasks in every loop of
  // CorotationalElements (kGrain, kProductGrain, kVertexGrain).
  for (const char* elements : {"tetrahedra", "hexahedra"}) {
    for (const char* method : {"large", "polar"}) {
      const std::vector<Vec3d> one = simulateBeam(elements, method, 1, 3);
      const std::vector<Vec3d> two = simulateBeam(elements, method, 2, 3);
      ASSERT_FALSE(one.empty());
      EXPECT_GT(std::abs(one.back().y() - 0.6), 1e-4) << "the beam must have moved";
      EXPECT_TRUE(bitwiseEqual(one, two)) << elements << " " << method;
    }
  }
}

}  // namespace
}  // namespace stroma::test
