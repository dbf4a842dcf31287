// SPDX-License-Identifier: MIT
// The bar of seed 000 figure 5.1 as share/mesh/make_bar.py writes it (4 x 4 x 12 nodes, 0.01 m
// apart, each cube split into 6 tetrahedra around its diagonal), built in memory for the kernel
// tests, with the zones of the scenes: layers of cubes along z.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <vector>

#include "DomainDecomposition/kernels/HybridDecomposition.h"

namespace stroma::domaindecomposition::test {

inline constexpr int kNx = 4, kNy = 4, kNz = 12;
inline constexpr double kSpacing = 0.01;

inline int barNode(int i, int j, int k) { return i + kNx * (j + kNy * k); }

/// The bar, E = 5 kPa, nu = 0.3, its z = 0 face fixed. Also the layer (0 to 10) of each element.
inline ElasticProblem makeBar(std::vector<int>& layerOfElement) {
  ElasticProblem bar;
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i)
        bar.points.emplace_back(i * kSpacing, j * kSpacing, k * kSpacing);
  std::array<int, 3> order{0, 1, 2};
  for (int k = 0; k + 1 < kNz; ++k)
    for (int j = 0; j + 1 < kNy; ++j)
      for (int i = 0; i + 1 < kNx; ++i) {
        std::sort(order.begin(), order.end());
        do {
          std::array<int, 3> corner{0, 0, 0};
          TetrahedronNodes t{};
          t[0] = barNode(i, j, k);
          for (int s = 0; s < 3; ++s) {
            ++corner[order[s]];
            t[s + 1] = barNode(i + corner[0], j + corner[1], k + corner[2]);
          }
          const Vec3& a = bar.points[t[0]];
          if ((bar.points[t[1]] - a).dot((bar.points[t[2]] - a).cross(bar.points[t[3]] - a)) < 0)
            std::swap(t[1], t[2]);
          bar.tetrahedra.push_back(t);
          layerOfElement.push_back(k);
        } while (std::next_permutation(order.begin(), order.end()));
      }
  bar.youngModulus = 5000;
  bar.poissonRatio = 0.3;
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i) bar.fixedNodes.push_back(barNode(i, j, 0));
  return bar;
}

/// Zones of `zoneCount` (1 to 5) along the bar, by layers of cubes: the fixed half first, the
/// rest shared by the others (seed 000 table 5.1's layout).
inline std::vector<int> barZones(const std::vector<int>& layerOfElement, int zoneCount) {
  // First layer of each zone after zone 0.
  static const std::vector<std::vector<int>> starts{{}, {5}, {5, 8}, {5, 7, 9}, {4, 6, 8, 10}};
  std::vector<int> zones;
  for (int layer : layerOfElement) {
    int z = 0;
    for (int start : starts[zoneCount - 1])
      if (layer >= start) ++z;
    zones.push_back(z);
  }
  return zones;
}

/// The loaded node: the middle of the free end's top edge.
inline int barTip() { return barNode(1, kNy - 1, kNz - 1); }

}  // namespace stroma::domaindecomposition::test
