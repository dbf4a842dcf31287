// SPDX-License-Identifier: MIT
#include "GridTransfer.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace stroma::multigrid {

namespace {

// Corner q of a hexahedron in local coordinates (TopologyTypes.h order).
constexpr int kCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

}  // namespace

bool makeLatticeGrid(std::span<const Vec3d> points, std::span<const Hexahedron> hexahedra,
                     const sparsegrid::GridBox* box, sparsegrid::SparseGrid& grid,
                     std::string& error) {
  if (hexahedra.empty()) {
    error = "the topology has no hexahedra";
    return false;
  }
  for (std::size_t e = 0; e < hexahedra.size(); ++e)
    for (Index v : hexahedra[e])
      if (v >= points.size()) {
        error = "hexahedron " + std::to_string(e) + " uses point " + std::to_string(v) + " of " +
                std::to_string(points.size());
        return false;
      }

  // The lattice: given, or the first hexahedron's edges and the bounding box of all.
  sparsegrid::GridBox lattice;
  if (box) {
    lattice = *box;
  } else {
    const Hexahedron& h = hexahedra.front();
    lattice.spacing =
        Vec3d(points[h[1]].x() - points[h[0]].x(), points[h[3]].y() - points[h[0]].y(),
              points[h[4]].z() - points[h[0]].z());
    lattice.origin = points[h[0]];
    for (const Hexahedron& hex : hexahedra)
      for (Index v : hex) lattice.origin = lattice.origin.cwiseMin(points[v]);
  }
  if (!(lattice.spacing.minCoeff() > 0)) {
    error =
        "the hexahedra are not cells of an axis-aligned lattice with positive spacing "
        "(first hexahedron's edges along x, y, z: " +
        std::to_string(lattice.spacing.x()) + ", " + std::to_string(lattice.spacing.y()) + ", " +
        std::to_string(lattice.spacing.z()) + ")";
    return false;
  }

  // Each hexahedron's cell, its corners checked against the lattice.
  const double tolerance = 1e-6 * lattice.spacing.minCoeff();
  std::vector<std::array<long long, 3>> coordinates(hexahedra.size());
  std::array<long long, 3> extent{0, 0, 0};
  for (std::size_t e = 0; e < hexahedra.size(); ++e) {
    const Vec3d local = (points[hexahedra[e][0]] - lattice.origin).cwiseQuotient(lattice.spacing);
    for (int a = 0; a < 3; ++a) {
      coordinates[e][a] = std::llround(local[a]);
      extent[a] = std::max(extent[a], coordinates[e][a] + 1);
    }
    for (int q = 0; q < 8; ++q) {
      Vec3d expected = lattice.origin;
      for (int a = 0; a < 3; ++a)
        expected[a] += double(coordinates[e][a] + kCorners[q][a]) * lattice.spacing[a];
      if ((points[hexahedra[e][q]] - expected).lpNorm<Eigen::Infinity>() > tolerance ||
          coordinates[e][0] < 0 || coordinates[e][1] < 0 || coordinates[e][2] < 0) {
        error = "hexahedron " + std::to_string(e) +
                " is not a cell of the axis-aligned lattice of the first one (corner " +
                std::to_string(q) +
                " is off its lattice point, or the corners are not in the "
                "order of TopologyTypes.h)";
        return false;
      }
    }
  }
  if (!box)
    for (int a = 0; a < 3; ++a) lattice.cells[a] = int(extent[a]);
  for (int a = 0; a < 3; ++a)
    if (extent[a] > lattice.cells[a]) {
      error = "a hexahedron lies outside the sparse grid's box";
      return false;
    }

  grid = sparsegrid::SparseGrid{};
  grid.box = lattice;
  grid.cells.resize(hexahedra.size());
  std::unordered_set<std::uint64_t> seen;
  for (std::size_t e = 0; e < hexahedra.size(); ++e) {
    grid.cells[e] =
        lattice.cellIndex(int(coordinates[e][0]), int(coordinates[e][1]), int(coordinates[e][2]));
    if (!seen.insert(grid.cells[e]).second) {
      error = "hexahedron " + std::to_string(e) + " repeats the cell of an earlier one";
      return false;
    }
  }
  grid.types.assign(hexahedra.size(), sparsegrid::CellType::full);
  grid.fractions.assign(hexahedra.size(), 1.0);
  grid.points.assign(points.begin(), points.end());
  grid.hexahedra.assign(hexahedra.begin(), hexahedra.end());
  return true;
}

Prolongation makeProlongation(const sparsegrid::SparseGrid& fine,
                              const sparsegrid::SparseGrid& coarse,
                              const std::vector<std::array<Index, 8>>& children) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(fine.points.size() * 8);
  std::vector<char> done(fine.points.size(), 0);
  for (std::size_t c = 0; c < children.size(); ++c) {
    const Hexahedron& parent = coarse.hexahedra[c];
    for (int q = 0; q < 8; ++q) {
      const Index child = children[c][q];
      if (child == kInvalidIndex) continue;
      for (int r = 0; r < 8; ++r) {
        const Index point = fine.hexahedra[child][r];
        if (done[point]) continue;
        done[point] = 1;
        // Local coordinates of corner r of child q in the parent: (c_q + c_r) / 2.
        double t[3];
        for (int a = 0; a < 3; ++a) t[a] = 0.5 * (kCorners[q][a] + kCorners[r][a]);
        for (int s = 0; s < 8; ++s) {
          double w = 1;
          for (int a = 0; a < 3; ++a) w *= kCorners[s][a] ? t[a] : 1 - t[a];
          if (w != 0) entries.emplace_back(int(point), int(parent[s]), w);
        }
      }
    }
  }
  Prolongation P(Eigen::Index(fine.points.size()), Eigen::Index(coarse.points.size()));
  P.setFromTriplets(entries.begin(), entries.end());
  return P;
}

Eigen::SparseMatrix<double> expandProlongation(const Prolongation& P, int dimension,
                                               const std::vector<char>& fixed) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(P.nonZeros()) * dimension);
  for (Eigen::Index i = 0; i < P.outerSize(); ++i)
    for (Prolongation::InnerIterator e(P, i); e; ++e)
      for (int d = 0; d < dimension; ++d) {
        const auto row = std::size_t(dimension * i + d);
        if (row < fixed.size() && fixed[row]) continue;
        entries.emplace_back(int(row), int(dimension * e.col() + d), e.value());
      }
  Eigen::SparseMatrix<double> expanded(dimension * P.rows(), dimension * P.cols());
  expanded.setFromTriplets(entries.begin(), entries.end());
  return expanded;
}

}  // namespace stroma::multigrid
