// SPDX-License-Identifier: MIT
// The nested grids of a geometric multigrid and the transfers between them (Nesme 2008, seed 001,
// ch. 5 sec. 3: "les operateurs de transferts ... sont triviaux" on nested grids).
//
// Level 0 is the simulated mesh: hexahedra that are cells of one axis-aligned regular lattice
// (a SparseGridTopology, a RegularGridTopology, or any hexahedral mesh laid out that way).
// Level l + 1 groups the cells of level l by 2 x 2 x 2 (sparsegrid::coarsenSparseGrid), keeping
// a coarse cell when one of its children is kept.
//
// Prolongation P_l (points of level l x points of level l + 1) is trilinear interpolation: a
// fine point of a child cell lies at local coordinates t in {0, 1/2, 1}^3 of its parent cell
// and takes the weights prod_a (c_a ? t_a : 1 - t_a) of the parent's corners c. A point shared
// by several parents gets the same weights from each (the weights of corners off the shared
// face are zero), so each row is written once. Restriction is P^T.
#pragma once

#include <Eigen/Sparse>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/Types.h"
#include "topology/SparseGridLevels.h"
#include "topology/TopologyTypes.h"

namespace stroma::multigrid {

/// Points x points, scalar: the same interpolation for each of the 3 components.
using Prolongation = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// The grid of level 0 from a mesh whose hexahedra are cells of an axis-aligned lattice, in the
/// mesh's numbering (grid.points = points, grid.hexahedra = hexahedra, every cell full with
/// fraction 1). `box`, when given (SparseGridTopology::sparseGrid()'s), fixes the lattice;
/// otherwise it is the bounding box of the hexahedra with the first one's edge lengths as
/// spacing. Returns false with `error` for an empty mesh, an index out of range, a hexahedron
/// that is not a lattice cell (rotated, distorted, wrongly ordered corners) or a repeated cell.
bool makeLatticeGrid(std::span<const Vec3d> points, std::span<const Hexahedron> hexahedra,
                     const sparsegrid::GridBox* box, sparsegrid::SparseGrid& grid,
                     std::string& error);

/// Trilinear prolongation from `coarse` to `fine`, with `children` as coarsenSparseGrid gives
/// them (per coarse cell, the fine cell at each corner or kInvalidIndex).
Prolongation makeProlongation(const sparsegrid::SparseGrid& fine,
                              const sparsegrid::SparseGrid& coarse,
                              const std::vector<std::array<Index, 8>>& children);

/// The prolongation of `dimension` components per point (rows and columns point-major:
/// dof = dimension * point + component), column-major for the Galerkin products, with the rows of
/// `fixed` degrees of freedom (non-zero entries, one per fine dof; may be empty) zeroed: the
/// coarse corrections then live in the space the projective constraints allow.
Eigen::SparseMatrix<double> expandProlongation(const Prolongation& P, int dimension,
                                               const std::vector<char>& fixed);

}  // namespace stroma::multigrid
