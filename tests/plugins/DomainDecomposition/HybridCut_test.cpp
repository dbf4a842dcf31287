// SPDX-License-Identifier: MIT
// Cutting a precomputed zone of the hybrid model (seed 000 section 4.5, figure 4.14): the zone
// becomes tensor-mass from the current state (no jump), the other zones' bases are untouched,
// and the iteration converges to the single-domain solution of the cut mesh.
#include <gtest/gtest.h>

#include <functional>

#include "BarMesh.h"
#include "DomainDecomposition/kernels/SingleDomainReference.h"

namespace stroma::domaindecomposition {
namespace {

std::size_t hashColumns(const precomputed::DeformationBasis& basis) {
  std::size_t hash = 0;
  const Eigen::MatrixXd& columns = basis.columns();
  for (Eigen::Index i = 0; i < columns.size(); ++i)
    hash = hash * 1000003u ^ std::hash<double>{}(columns.data()[i]);
  return hash;
}

TEST(HybridCut, ACutZoneBecomesTensorMassAndTheOthersKeepTheirBases) {
  std::vector<int> layers;
  ElasticProblem bar = test::makeBar(layers);
  const std::vector<int> zones = test::barZones(layers, 3);  // layers 0-4, 5-7, 8-10
  Loads loads;
  loads.forceNodes = {test::barTip()};
  loads.forces = {Vec3(0, -0.01, 0)};
  HybridDecomposition hybrid;
  std::string error;
  ASSERT_TRUE(
      hybrid.setup(bar, zones, std::vector<ZoneModel>(3, ZoneModel::precomputed), loads, {}, error))
      << error;
  for (int k = 0; k < 100; ++k) hybrid.iterate();
  const std::size_t hash0 = hashColumns(*hybrid.basis(0));
  const std::size_t hash2 = hashColumns(*hybrid.basis(2));
  const Eigen::VectorXd before = hybrid.displacement();

  // Cut the 6 tetrahedra of one cube of layer 6 (zone 1), indices in decreasing order.
  const int firstOfCube = 6 * (6 * 9 + 4);  // layer 6, cube (1, 1)
  std::vector<int> removed;
  for (int e = firstOfCube + 5; e >= firstOfCube; --e) removed.push_back(e);
  std::vector<int> converted;
  ASSERT_TRUE(hybrid.removeTetrahedra(removed, converted, error)) << error;
  EXPECT_EQ(converted, std::vector<int>{1});
  EXPECT_EQ(hybrid.zoneModel(1), ZoneModel::tensorMass);
  EXPECT_EQ(hybrid.basis(1), nullptr);
  EXPECT_EQ(hybrid.tetrahedra().size(), bar.tetrahedra.size() - 6);
  // No jump: the state is the one before the cut.
  EXPECT_EQ((hybrid.displacement() - before).norm(), 0.0);
  // The other zones' stored bases are bit for bit the same.
  ASSERT_NE(hybrid.basis(0), nullptr);
  ASSERT_NE(hybrid.basis(2), nullptr);
  EXPECT_EQ(hashColumns(*hybrid.basis(0)), hash0);
  EXPECT_EQ(hashColumns(*hybrid.basis(2)), hash2);

  // The cut bar converges to its own single-domain solution.
  bar.tetrahedra = hybrid.tetrahedra();
  Eigen::VectorXd reference;
  ASSERT_TRUE(solveSingleDomain(bar, loads, reference, error)) << error;
  const double edge = computeMeanEdgeLength(bar.points, bar.tetrahedra);
  EXPECT_GT(compareDisplacements(hybrid.displacement(), reference).max, 1e-6 * edge);
  for (int k = 0; k < 2000; ++k) hybrid.iterate();
  EXPECT_LT(compareDisplacements(hybrid.displacement(), reference).max, 1e-6 * edge);
}

TEST(HybridCut, ARemovedIndexOutOfRangeIsRefused) {
  std::vector<int> layers;
  const ElasticProblem bar = test::makeBar(layers);
  HybridDecomposition hybrid;
  std::string error;
  ASSERT_TRUE(hybrid.setup(bar, test::barZones(layers, 2),
                           std::vector<ZoneModel>(2, ZoneModel::precomputed), {}, {}, error));
  std::vector<int> converted;
  EXPECT_FALSE(hybrid.removeTetrahedra({594}, converted, error));
  EXPECT_NE(error.find("594 is out of range"), std::string::npos) << error;
}

}  // namespace
}  // namespace stroma::domaindecomposition
