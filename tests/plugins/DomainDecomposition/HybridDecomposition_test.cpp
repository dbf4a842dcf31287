// SPDX-License-Identifier: MIT
// The hybrid model's iteration (plugins/DomainDecomposition/kernels/HybridDecomposition.h) on
// the bar of seed 000 figure 5.1: convergence to the single-domain static solution with 2 to 5
// zones (seed 000 section 5.1), the faster convergence of imposed displacements, Jacobi, tensor-
// mass zones, cuts converting a zone, and the bad-input messages.
#include <gtest/gtest.h>

#include <functional>

#include "BarMesh.h"
#include "DomainDecomposition/kernels/SingleDomainReference.h"

namespace stroma::domaindecomposition {
namespace {

using test::barTip;
using test::barZones;
using test::makeBar;

Loads tipForce() {
  Loads loads;
  loads.forceNodes = {barTip()};
  loads.forces = {Vec3(0, -0.01, 0)};  // N: a 7 mm deflection
  return loads;
}

Loads tipDisplacement() {
  Loads loads;
  loads.imposedNodes = {barTip()};
  loads.imposedDisplacements = {Vec3(0, -0.005, 0)};
  return loads;
}

/// Iterations until the largest nodal error falls below `tolerance` (at most `limit`), with
/// the mean error after each iteration in `history`.
int iterateUntil(HybridDecomposition& hybrid, const Eigen::VectorXd& reference, double tolerance,
                 int limit, std::vector<double>& history) {
  for (int k = 1; k <= limit; ++k) {
    hybrid.iterate();
    const DisplacementError e = compareDisplacements(hybrid.displacement(), reference);
    history.push_back(e.mean);
    if (e.max < tolerance) return k;
  }
  return limit + 1;
}

struct BarRun {
  int iterations = 0;
  std::vector<double> history;
};

BarRun runBar(int zoneCount, const Loads& loads, const std::vector<ZoneModel>& models = {},
              DecompositionOptions options = {}, int limit = 3000) {
  std::vector<int> layers;
  const ElasticProblem bar = makeBar(layers);
  const std::vector<int> zones = barZones(layers, zoneCount);
  Eigen::VectorXd reference;
  std::string error;
  EXPECT_TRUE(solveSingleDomain(bar, loads, reference, error)) << error;
  HybridDecomposition hybrid;
  const std::vector<ZoneModel> zoneModels =
      models.empty() ? std::vector<ZoneModel>(zoneCount, ZoneModel::precomputed) : models;
  EXPECT_TRUE(hybrid.setup(bar, zones, zoneModels, loads, options, error)) << error;
  const double edge = computeMeanEdgeLength(bar.points, bar.tetrahedra);
  BarRun run;
  run.iterations = iterateUntil(hybrid, reference, 1e-6 * edge, limit, run.history);
  return run;
}

TEST(HybridDecomposition, ConvergesToTheSingleDomainSolutionWith2To5Zones) {
  for (int zones = 2; zones <= 5; ++zones) {
    const BarRun run = runBar(zones, tipForce());
    EXPECT_LE(run.iterations, 3000) << zones << " zones";
    // Multiplicative Schwarz: the error decreases at every iteration.
    for (std::size_t k = 1; k < run.history.size(); ++k) {
      EXPECT_LE(run.history[k], run.history[k - 1] * (1 + 1e-9) + 1e-18)
          << zones << " zones, iteration " << k + 1;
    }
  }
}

TEST(HybridDecomposition, ImposedDisplacementsConvergeFasterThanForces) {
  for (int zones = 2; zones <= 5; ++zones) {
    const BarRun force = runBar(zones, tipForce());
    const BarRun imposed = runBar(zones, tipDisplacement());
    EXPECT_LT(imposed.iterations, force.iterations) << zones << " zones";
  }
}

TEST(HybridDecomposition, JacobiConvergesSlowerThanGaussSeidel) {
  DecompositionOptions jacobi;
  jacobi.iteration = InterfaceIteration::jacobi;
  const BarRun gs = runBar(3, tipForce());
  const BarRun j = runBar(3, tipForce(), {}, jacobi, 6000);
  EXPECT_LE(j.iterations, 6000);
  EXPECT_GT(j.iterations, gs.iterations);
}

TEST(HybridDecomposition, TensorMassZonesConverge) {
  const std::vector<ZoneModel> mixed{ZoneModel::precomputed, ZoneModel::tensorMass,
                                     ZoneModel::precomputed};
  const BarRun direct = runBar(3, tipForce(), mixed);
  EXPECT_LE(direct.iterations, 3000);
  DecompositionOptions relaxed;
  relaxed.tensorMassSolve = TensorMassSolve::relaxation;
  relaxed.relaxationSteps = 20;
  relaxed.relaxationDamping = 0.1;  // a short zone held at both ends: stiffer than the bar
  const BarRun relaxation = runBar(3, tipDisplacement(), mixed, relaxed, 20000);
  EXPECT_LE(relaxation.iterations, 20000);
}

TEST(HybridDecomposition, TheCondensedInterfaceIsExactInOneIteration) {
  DecompositionOptions schur;
  schur.iteration = InterfaceIteration::schur;
  for (int zones = 1; zones <= 5; ++zones) {
    EXPECT_EQ(runBar(zones, tipForce(), {}, schur, 1).iterations, 1) << zones << " zones";
    EXPECT_EQ(runBar(zones, tipDisplacement(), {}, schur, 1).iterations, 1) << zones << " zones";
  }
}

TEST(HybridDecomposition, TheCondensedInterfaceNeedsPrecomputedZones) {
  std::vector<int> layers;
  const ElasticProblem bar = makeBar(layers);
  DecompositionOptions schur;
  schur.iteration = InterfaceIteration::schur;
  HybridDecomposition hybrid;
  std::string error;
  EXPECT_FALSE(hybrid.setup(bar, barZones(layers, 2),
                            {ZoneModel::precomputed, ZoneModel::tensorMass}, tipForce(), schur,
                            error));
  EXPECT_NE(error.find("needs every zone precomputed; zone 1 is tensor-mass"), std::string::npos)
      << error;
  ASSERT_TRUE(hybrid.setup(bar, barZones(layers, 2),
                           {ZoneModel::precomputed, ZoneModel::precomputed}, tipForce(), schur,
                           error))
      << error;
  std::vector<int> converted;
  EXPECT_FALSE(hybrid.removeTetrahedra({0}, converted, error));
  EXPECT_NE(error.find("does not follow cuts"), std::string::npos) << error;
}

}  // namespace
}  // namespace stroma::domaindecomposition
