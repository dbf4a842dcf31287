// SPDX-License-Identifier: MIT
// The data of a sparse hexahedral grid and of its nested finer levels (Nesme 2008, seed 001,
// ch. 3 and 4), in the framework so that every plugin reaches it through
// Topology::sparseGrid() and Topology::sparseGridFinerLevels(): the non-uniform elements
// condense from the finer levels, multigrid and T-node solvers walk the nesting. The
// SparseGrid plugin builds these (plugins/SparseGrid/src/SparseGrid.h: buildSparseGrid,
// coarsenSparseGrid).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/DataTraits.h"
#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma::sparsegrid {

enum class CellType : std::uint8_t { empty, boundary, full };

/// A regular box of cells: `cells` per axis (each >= 1), lower corner `origin`, cell size
/// `spacing` (each > 0).
struct GridBox {
  std::array<int, 3> cells{1, 1, 1};
  Vec3d origin = Vec3d::Zero();
  Vec3d spacing = Vec3d::Ones();

  std::uint64_t cellCount() const { return std::uint64_t(cells[0]) * cells[1] * cells[2]; }
  std::uint64_t pointCount() const {
    return std::uint64_t(cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1);
  }
  std::uint64_t cellIndex(int i, int j, int k) const {
    return i + std::uint64_t(cells[0]) * (j + std::uint64_t(cells[1]) * k);
  }
  /// (i, j, k) of a cell index.
  std::array<int, 3> cellCoordinates(std::uint64_t index) const {
    const std::uint64_t layer = std::uint64_t(cells[0]) * cells[1];
    const auto k = int(index / layer), rest = int(index % layer);
    return {rest % cells[0], rest / cells[0], k};
  }
};

/// The kept (non-empty) cells of a box, as a hexahedral mesh with per-cell data.
struct SparseGrid {
  GridBox box;
  std::vector<std::uint64_t> cells;   ///< cell index in `box` of each kept cell (Numbering)
  std::vector<CellType> types;        ///< boundary or full, per kept cell
  std::vector<double> fractions;      ///< filled volume fraction in [0, 1], per kept cell
  std::vector<Vec3d> points;          ///< corners of the kept cells, shared ones once
  std::vector<Hexahedron> hexahedra;  ///< per kept cell, indices into `points`

  std::size_t count(CellType type) const {
    return std::size_t(std::count(types.begin(), types.end(), type));
  }
  /// Sum over the kept cells of fraction x cell volume.
  double filledVolume() const {
    double sum = 0;
    for (double f : fractions) sum += f;
    return sum * box.spacing.prod();
  }
};

/// A finer level of a sparse grid: its cells, and for each cell of the next coarser level its 8
/// children here (child q at corner q of the coarse hexahedron, TopologyTypes.h order;
/// kInvalidIndex for an empty child), as coarsenSparseGrid gives them.
struct FinerLevel {
  SparseGrid grid;
  std::vector<std::array<Index, 8>> parentsChildren;
};

}  // namespace stroma::sparsegrid

namespace stroma {
template <>
struct EnumKeywords<sparsegrid::CellType> {
  static constexpr std::array<std::string_view, 3> names{"empty", "boundary", "full"};
};
}  // namespace stroma
