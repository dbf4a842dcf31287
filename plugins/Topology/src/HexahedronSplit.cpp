// SPDX-License-Identifier: MIT
#include "HexahedronSplit.h"

#include <algorithm>
#include <array>
#include <deque>

#include "topology/MeshAdjacency.h"

namespace stroma {

namespace {

// Local vertex tables (TopologyTypes.h numbering); each tetrahedron is positive.
constexpr std::array<std::array<int, 4>, 6> kSix{
    {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}}};
// Five-split variants: corners 1 3 4 6 around the central (0 2 5 7), and the other way round.
constexpr std::array<std::array<std::array<int, 4>, 5>, 2> kFive{
    {{{{1, 0, 5, 2}, {3, 0, 2, 7}, {4, 0, 7, 5}, {6, 2, 5, 7}, {0, 2, 7, 5}}},
     {{{0, 1, 3, 4}, {2, 1, 6, 3}, {5, 1, 4, 6}, {7, 3, 6, 4}, {1, 3, 4, 6}}}}};
constexpr std::array<std::array<int, 4>, 2> kCentral{{{0, 2, 5, 7}, {1, 3, 4, 6}}};

// Vertex permutations of the mirrors across the middle planes u, v and w.
constexpr std::array<std::array<int, 8>, 3> kMirror{
    {{1, 0, 3, 2, 5, 4, 7, 6}, {3, 2, 1, 0, 7, 6, 5, 4}, {4, 5, 6, 7, 0, 1, 2, 3}}};

/// The diagonal a five-split variant cuts local face `face` with, as a sorted global pair.
Edge fiveSplitDiagonal(const Hexahedron& h, int variant, int face) {
  Edge d{kInvalidIndex, kInvalidIndex};
  int n = 0;
  for (int local : kHexahedronFaces[face]) {
    const auto& central = kCentral[variant];
    if (std::find(central.begin(), central.end(), local) != central.end() && n < 2)
      d[n++] = h[local];
  }
  if (d[0] > d[1]) std::swap(d[0], d[1]);
  return d;
}

}  // namespace

std::vector<Tetrahedron> splitHexahedraInSix(std::span<const Hexahedron> hexahedra,
                                             std::span<const std::uint8_t> mirrors) {
  std::vector<Tetrahedron> tetrahedra;
  tetrahedra.reserve(hexahedra.size() * 6);
  for (std::size_t e = 0; e < hexahedra.size(); ++e) {
    Hexahedron h = hexahedra[e];
    bool odd = false;
    if (e < mirrors.size())
      for (int axis = 0; axis < 3; ++axis)
        if (mirrors[e] & (1u << axis)) {
          Hexahedron mirrored;
          for (int v = 0; v < 8; ++v) mirrored[v] = h[kMirror[axis][v]];
          h = mirrored;
          odd = !odd;
        }
    for (const auto& t : kSix) {
      // A mirror reverses orientation: an odd number of them is undone by a swap.
      if (odd)
        tetrahedra.push_back({h[t[0]], h[t[1]], h[t[3]], h[t[2]]});
      else
        tetrahedra.push_back({h[t[0]], h[t[1]], h[t[2]], h[t[3]]});
    }
  }
  return tetrahedra;
}

std::vector<std::uint8_t> alternatingMirrors(const GridSize& cells) {
  std::vector<std::uint8_t> mirrors;
  mirrors.reserve(cells.points());
  for (int k = 0; k < cells.nz; ++k)
    for (int j = 0; j < cells.ny; ++j)
      for (int i = 0; i < cells.nx; ++i)
        mirrors.push_back(static_cast<std::uint8_t>((i & 1) | ((j & 1) << 1) | ((k & 1) << 2)));
  return mirrors;
}

std::optional<GridSize> findGridCells(std::span<const Hexahedron> hexahedra) {
  if (hexahedra.empty()) return std::nullopt;
  // The first hexahedron gives the points per row and per layer.
  const Hexahedron& first = hexahedra.front();
  if (first[0] != 0 || first[1] != 1 || first[3] <= 1) return std::nullopt;
  const long long row = first[3];
  const long long layer = first[4];
  if (layer <= 0 || layer % row != 0) return std::nullopt;
  GridSize cells{static_cast<int>(row - 1), static_cast<int>(layer / row - 1), 0};
  if (cells.nx < 1 || cells.ny < 1) return std::nullopt;
  const std::size_t perLayer = std::size_t(cells.nx) * cells.ny;
  if (hexahedra.size() % perLayer != 0) return std::nullopt;
  cells.nz = static_cast<int>(hexahedra.size() / perLayer);
  const GridSize points{cells.nx + 1, cells.ny + 1, cells.nz + 1};
  const std::vector<Hexahedron> expected = makeGridHexahedra(points);
  if (!std::equal(expected.begin(), expected.end(), hexahedra.begin(), hexahedra.end()))
    return std::nullopt;
  return cells;
}

FiveSplit splitHexahedraInFive(std::span<const Hexahedron> hexahedra) {
  FiveSplit result;
  const HexahedronFaces faces = computeHexahedronFaces(hexahedra);
  std::vector<int> variant(hexahedra.size(), -1);
  // Each connected part starts from its first hexahedron with variant 0; neighbours across a
  // face take the variant whose diagonal on that face is the same.
  std::deque<std::size_t> queue;
  for (std::size_t start = 0; start < hexahedra.size(); ++start) {
    if (variant[start] >= 0) continue;
    variant[start] = 0;
    queue.push_back(start);
    while (!queue.empty()) {
      const std::size_t h = queue.front();
      queue.pop_front();
      for (int f = 0; f < 6; ++f) {
        const Index face = faces.facesInElement[h][f];
        const Edge diagonal = fiveSplitDiagonal(hexahedra[h], variant[h], f);
        for (Index n : faces.elementsAroundFace[face]) {
          if (n == h || variant[n] >= 0) continue;
          int g = 0;
          while (g < 5 && faces.facesInElement[n][g] != face) ++g;
          for (int v = 0; v < 2; ++v)
            if (fiveSplitDiagonal(hexahedra[n], v, g) == diagonal) {
              variant[n] = v;
              queue.push_back(n);
              break;
            }
        }
      }
    }
  }
  // Faces shared by two hexahedra whose diagonals differ.
  for (std::size_t face = 0; face < faces.faces.size(); ++face) {
    const auto around = faces.elementsAroundFace[face];
    if (around.size() != 2) continue;
    auto localFace = [&](Index e) {
      int g = 0;
      while (g < 5 && faces.facesInElement[e][g] != face) ++g;
      return g;
    };
    const Index a = around[0], b = around[1];
    if (fiveSplitDiagonal(hexahedra[a], variant[a], localFace(a)) !=
        fiveSplitDiagonal(hexahedra[b], variant[b], localFace(b)))
      ++result.mismatchedFaces;
  }
  result.tetrahedra.reserve(hexahedra.size() * 5);
  for (std::size_t e = 0; e < hexahedra.size(); ++e)
    for (const auto& t : kFive[variant[e]])
      result.tetrahedra.push_back(
          {hexahedra[e][t[0]], hexahedra[e][t[1]], hexahedra[e][t[2]], hexahedra[e][t[3]]});
  return result;
}

}  // namespace stroma
