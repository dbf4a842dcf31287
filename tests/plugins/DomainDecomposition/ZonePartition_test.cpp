// SPDX-License-Identifier: MIT
// Partitions of the hybrid model (plugins/DomainDecomposition/kernels/ZonePartition.h) and the
// messages for partitions and boundary conditions it cannot solve.
#include "DomainDecomposition/kernels/ZonePartition.h"

#include <gtest/gtest.h>

#include "BarMesh.h"

namespace stroma::domaindecomposition {
namespace {

TEST(ZonePartition, BoxesGiveTheZoneOfTheFirstBoxHoldingTheBarycentre) {
  std::vector<int> layers;
  const ElasticProblem bar = test::makeBar(layers);
  Box low, high;
  low << -1, -1, -1, 1, 1, 0.05;
  high << -1, -1, 0.04, 1, 1, 1;  // overlaps the first: the first wins
  const std::vector<int> zones = partitionFromBoxes(bar.points, bar.tetrahedra, {low, high});
  for (std::size_t e = 0; e < zones.size(); ++e) EXPECT_EQ(zones[e], layers[e] < 5 ? 0 : 1);
  EXPECT_EQ(checkPartition(zones, bar.tetrahedra.size(), 2), "");
}

TEST(ZonePartition, AnElementInNoZoneIsNamed) {
  std::vector<int> layers;
  const ElasticProblem bar = test::makeBar(layers);
  Box low;
  low << -1, -1, -1, 1, 1, 0.1;  // the last layer (z from 0.1 to 0.11 m) is left out
  const std::vector<int> zones = partitionFromBoxes(bar.points, bar.tetrahedra, {low});
  const std::string message = checkPartition(zones, bar.tetrahedra.size(), 1);
  EXPECT_NE(message.find("54 tetrahedra are in no zone: elements 540, 541"), std::string::npos)
      << message;

  HybridDecomposition hybrid;
  std::string error;
  EXPECT_FALSE(hybrid.setup(bar, zones, {ZoneModel::precomputed}, {}, {}, error));
  EXPECT_NE(error.find("in no zone"), std::string::npos) << error;
}

TEST(ZonePartition, MetisGivesBalancedZonesCoveringTheMesh) {
  std::vector<int> layers;
  const ElasticProblem bar = test::makeBar(layers);
  std::string error;
  const std::vector<int> zones = partitionWithMetis(bar.tetrahedra, bar.points.size(), 4, error);
  ASSERT_EQ(zones.size(), bar.tetrahedra.size()) << error;
  EXPECT_EQ(checkPartition(zones, bar.tetrahedra.size(), 4), "");
  std::vector<int> count(4, 0);
  for (int z : zones) ++count[z];
  for (int c : count) EXPECT_NEAR(c, 594 / 4.0, 0.1 * 594);  // METIS's default imbalance: 3 %
}

TEST(ZonePartition, ZonesWithNoFixedNodeAndOnlyForcesAreRefused) {
  std::vector<int> layers;
  ElasticProblem bar = test::makeBar(layers);
  bar.fixedNodes.clear();
  Loads loads;
  loads.forceNodes = {test::barTip()};
  loads.forces = {Vec3(0, -0.01, 0)};
  HybridDecomposition hybrid;
  std::string error;
  EXPECT_FALSE(hybrid.setup(bar, test::barZones(layers, 3),
                            std::vector<ZoneModel>(3, ZoneModel::precomputed), loads, {}, error));
  EXPECT_NE(error.find("zones 0, 1, 2 (connected) have no fixed node and no imposed displacement"),
            std::string::npos)
      << error;
  // An imposed displacement holds the bar: accepted.
  loads.imposedNodes = {0};
  loads.imposedDisplacements = {Vec3::Zero()};
  EXPECT_TRUE(hybrid.setup(bar, test::barZones(layers, 3),
                           std::vector<ZoneModel>(3, ZoneModel::precomputed), loads, {}, error))
      << error;
}

}  // namespace
}  // namespace stroma::domaindecomposition
