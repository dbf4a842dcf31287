// SPDX-License-Identifier: MIT
// Small meshes for the topology tests: the unit cube split into 5 or 6 tetrahedra, and grids of
// hexahedra, in the vertex orders of TopologyTypes.h.
#pragma once

#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma::test {

/// Corners of the unit cube, numbered as the vertices of a hexahedron.
inline std::vector<Vec3d> unitCubePoints() {
  return {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 1, 0), Vec3d(0, 1, 0),
          Vec3d(0, 0, 1), Vec3d(1, 0, 1), Vec3d(1, 1, 1), Vec3d(0, 1, 1)};
}

/// Four corner tetrahedra and a central one.
inline std::vector<Tetrahedron> cubeInFiveTetrahedra() {
  return {{1, 0, 5, 2}, {3, 0, 2, 7}, {4, 0, 7, 5}, {6, 2, 5, 7}, {0, 2, 7, 5}};
}

/// The six tetrahedra around the diagonal 0-6.
inline std::vector<Tetrahedron> cubeInSixTetrahedra() {
  return {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
}

/// A grid of n x n x n unit hexahedra: (n+1)^3 points, x fastest.
struct HexGrid {
  std::vector<Vec3d> points;
  std::vector<Hexahedron> hexahedra;
};
inline HexGrid hexGrid(int n) {
  HexGrid grid;
  const int m = n + 1;
  auto id = [m](int i, int j, int k) { return Index(i + m * (j + m * k)); };
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) grid.points.emplace_back(i, j, k);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        grid.hexahedra.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
                                  id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1),
                                  id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return grid;
}

}  // namespace stroma::test
