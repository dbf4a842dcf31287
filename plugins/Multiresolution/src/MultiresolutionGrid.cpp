// SPDX-License-Identifier: MIT
#include "MultiresolutionGrid.h"

#include <algorithm>
#include <cstdint>

namespace stroma::multiresolution {

namespace {

// Corner offsets of a hexahedron in TopologyTypes.h order.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

struct Lattice {
  std::array<int, 3> size;  // fine lattice points per axis
  std::int64_t id(int i, int j, int k) const {
    return i + std::int64_t(size[0]) * (j + std::int64_t(size[1]) * k);
  }
};

}  // namespace

MixedGrid makeMixedGrid(const std::array<int, 3>& nodes, const Vec3d& min, const Vec3d& max,
                        const std::vector<char>& refined) {
  const std::array<int, 3> cells{nodes[0] - 1, nodes[1] - 1, nodes[2] - 1};
  const Lattice lattice{{2 * cells[0] + 1, 2 * cells[1] + 1, 2 * cells[2] + 1}};
  auto cellIndex = [&](int a, int b, int c) { return a + cells[0] * (b + cells[1] * c); };

  // 1. The lattice points that some cell uses, numbered in lattice order.
  const std::int64_t latticeSize = lattice.id(0, 0, lattice.size[2]);
  std::vector<Index> number(static_cast<std::size_t>(latticeSize), kInvalidIndex);
  for (int c = 0; c < cells[2]; ++c)
    for (int b = 0; b < cells[1]; ++b)
      for (int a = 0; a < cells[0]; ++a) {
        const int step = refined[cellIndex(a, b, c)] ? 1 : 2;
        for (int k = 2 * c; k <= 2 * c + 2; k += step)
          for (int j = 2 * b; j <= 2 * b + 2; j += step)
            for (int i = 2 * a; i <= 2 * a + 2; i += step) number[lattice.id(i, j, k)] = 0;
      }
  MixedGrid grid;
  for (int k = 0; k < lattice.size[2]; ++k)
    for (int j = 0; j < lattice.size[1]; ++j)
      for (int i = 0; i < lattice.size[0]; ++i) {
        Index& n = number[lattice.id(i, j, k)];
        if (n == kInvalidIndex) continue;
        n = static_cast<Index>(grid.points.size());
        const Vec3d s(double(i) / (lattice.size[0] - 1), double(j) / (lattice.size[1] - 1),
                      double(k) / (lattice.size[2] - 1));
        grid.points.push_back(min + (max - min).cwiseProduct(s));
      }

  // 2. The hexahedra: a kept cell, or the 8 children of a refined one.
  auto addHexahedron = [&](int i, int j, int k, int size, int level) {
    Hexahedron h;
    for (int v = 0; v < 8; ++v)
      h[v] = number[lattice.id(i + size * kCorner[v][0], j + size * kCorner[v][1],
                               k + size * kCorner[v][2])];
    grid.hexahedra.push_back(h);
    grid.cellLevels.push_back(level);
  };
  for (int c = 0; c < cells[2]; ++c)
    for (int b = 0; b < cells[1]; ++b)
      for (int a = 0; a < cells[0]; ++a) {
        if (!refined[cellIndex(a, b, c)]) {
          addHexahedron(2 * a, 2 * b, 2 * c, 2, 0);
          continue;
        }
        for (int z = 0; z < 2; ++z)
          for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) addHexahedron(2 * a + x, 2 * b + y, 2 * c + z, 1, 1);
      }

  // 3. T-nodes: a fine node (some odd coordinate) on the boundary of a kept cell. Along an odd
  // axis the node is inside the coarse cells' span, between lattice points l - 1 and l + 1
  // (weight 1/2 each); along an even axis it is on a coarse plane, shared by the cells on both
  // sides. The node is a T-node when one of the cells around it is kept.
  for (int k = 0; k < lattice.size[2]; ++k)
    for (int j = 0; j < lattice.size[1]; ++j)
      for (int i = 0; i < lattice.size[0]; ++i) {
        const Index n = number[lattice.id(i, j, k)];
        const std::array<int, 3> l{i, j, k};
        const int odd = (i & 1) + (j & 1) + (k & 1);
        if (n == kInvalidIndex || odd == 0 || odd == 3) continue;
        // Coarse cells around the node, per axis: one (odd) or up to two (even).
        std::array<std::array<int, 2>, 3> around;
        std::array<int, 3> count{};
        for (int d = 0; d < 3; ++d) {
          if (l[d] & 1) {
            around[d][count[d]++] = (l[d] - 1) / 2;
          } else {
            if (l[d] / 2 - 1 >= 0) around[d][count[d]++] = l[d] / 2 - 1;
            if (l[d] / 2 < cells[d]) around[d][count[d]++] = l[d] / 2;
          }
        }
        bool nextToKeptCell = false;
        for (int x = 0; x < count[0]; ++x)
          for (int y = 0; y < count[1]; ++y)
            for (int z = 0; z < count[2]; ++z)
              if (!refined[cellIndex(around[0][x], around[1][y], around[2][z])])
                nextToKeptCell = true;
        if (!nextToKeptCell) continue;
        // Parents: the corners of the coarse edge or face, each odd axis giving two sides.
        TNode t;
        t.node = n;
        const double weight = odd == 1 ? 0.5 : 0.25;
        for (int corner = 0; corner < (1 << odd); ++corner) {
          std::array<int, 3> p = l;
          int bit = 0;
          for (int d = 0; d < 3; ++d)
            if (l[d] & 1) p[d] += (corner >> bit++) & 1 ? 1 : -1;
          t.parents[t.parentCount] = number[lattice.id(p[0], p[1], p[2])];
          t.weights[t.parentCount] = weight;
          ++t.parentCount;
        }
        grid.tNodes.push_back(t);
      }
  return grid;
}

}  // namespace stroma::multiresolution
