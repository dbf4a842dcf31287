// SPDX-License-Identifier: MIT
// A box grid whose cells are either kept (level 0) or refined once into 2 x 2 x 2 children
// (level 1), and its T-nodes: the fine nodes lying on an edge or a face of a kept cell (seed 001,
// chapter 4 section 4, figure 4.5). A T-node is not a degree of freedom of its own: its
// displacement is the interpolation of the kept cell's nodes it lies between (linear on an edge,
// bilinear on a face), and its forces go to them through the transpose (Algorithm 1).
//
// Nodes live on the fine lattice (2 (n - 1) + 1 points per axis); the coarse nodes are those with
// even lattice coordinates. Points are numbered in increasing lattice order (x fastest), cells
// coarse cell by coarse cell (x fastest), a refined cell's children x fastest. Hexahedron vertex
// order: TopologyTypes.h.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma::multiresolution {

/// A fine node constrained to a coarse edge (2 parents) or face (4 parents).
struct TNode {
  Index node = kInvalidIndex;
  int parentCount = 0;
  std::array<Index, 4> parents{};
  std::array<double, 4> weights{};
};

struct MixedGrid {
  std::vector<Vec3d> points;
  std::vector<Hexahedron> hexahedra;
  std::vector<int> cellLevels;  ///< per hexahedron: 0 kept coarse cell, 1 refined child
  std::vector<TNode> tNodes;    ///< in increasing node order
};

/// `nodes`: coarse grid points per axis (each >= 2); `refined`: one flag per coarse cell
/// (x fastest). Precondition (checked by the caller): sizes consistent, min < max on each axis.
MixedGrid makeMixedGrid(const std::array<int, 3>& nodes, const Vec3d& min, const Vec3d& max,
                        const std::vector<char>& refined);

}  // namespace stroma::multiresolution
