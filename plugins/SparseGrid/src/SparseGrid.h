// SPDX-License-Identifier: MIT
// A sparse hexahedral grid built around a triangle surface (Nesme 2008, seed 001, ch. 3 sec. 1
// and figure 3.3), and its coarser levels by 2 x 2 x 2 grouping.
//
// buildSparseGrid() classifies every cell of a regular box of cells:
// 1. boundary: the cell (a closed box) overlaps a triangle of the surface, by the exact
//    separating-axis test (TriangleBoxOverlap.h);
// 2. empty: reached by a flood fill of the outside, started from every non-boundary cell on the
//    border of the box and going through the faces of non-boundary cells (6-connectivity);
// 3. full: the cells left, enclosed by boundary cells.
// Only the orientation-free geometry of the triangles is used: inside-out, non-manifold or
// self-intersecting surfaces give the same cells as a clean one covering the same points. A hole
// narrower than a cell never lets the flood in (a cell in the hole touches its rim); one wider
// than about sqrt(3) cells does.
//
// The filled volume fraction of each boundary cell is measured on a finer sub-grid of
// `samples`^3 sub-cells per boundary cell, classified the same way: sub-cells overlapping a
// triangle, then a flood fill through the other sub-cells of the boundary cells, started from
// those that face an empty cell or the border of the box. Sub-cells it does not reach are inside
// and count 1. A sub-cell that the surface crosses counts the inside share of 3 x 3 x 3
// stratified sample points (one per part, at a pseudo-random offset, so that the estimate is
// unbiased): a point takes the state of a neighbouring sub-cell of known state that it reaches
// without crossing the sub-cell's triangles, or else the parity of the crossings to one decides.
// Walls inside the volume stay filled and open sheets empty. The sub-cell flood never enters a
// full cell: a hole between a sub-cell and a cell wide only lowers the fractions of the boundary
// cells around it. Full cells have fraction 1. Measured with samples = 4 (SparseGrid_test.cpp):
// the total volume (full cells + fractions) of a sphere is within 0.07 % of the exact one at 8
// cells across, 0.015 % at 16, 0.006 % at 32.
//
// Numbering: cell (i, j, k) of a box of cx x cy x cz cells is i + cx (j + cy k); grid point
// (i, j, k) is i + (cx+1) (j + (cy+1) k). The mesh follows SOFA's SparseGridTopology, so that
// scenes naming points or hexahedra by index keep working: the kept cells are the boundary
// cells, then the full cells, each in increasing cell index (a coarser level made by
// coarsenSparseGrid: x slowest, z fastest, as SOFA's buildFromFiner); the points are the kept
// cells' corners, shared ones once, by increasing (x, y, z) (x slowest, z fastest: SOFA's map
// from positions to indices). Each hexahedron lists its corners in the order of
// TopologyTypes.h: (i,j,k) (i+1,j,k) (i+1,j+1,k) (i,j+1,k), then the same at k+1; with a
// positive spacing every hexahedron is positively oriented.
//
// Cost: the surface pass tests each triangle against the cells of its bounding box, then the
// sub-cells of the boundary cells it overlaps; both floods visit each (sub-)cell once; each
// surface sub-cell tests 27 segments against its few triangles. About 13 bytes per cell of the
// box are allocated while building, plus the sub-cells (estimateBuildBytes()). Measured: a
// sphere of 20480 triangles in 47^3 = 103823 cells in 0.2 to 0.5 s, 10^6 cells in 1 to 2 s
// (Release, one core; SparseGrid_test BuildsHundredThousandCellsQuickly).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/Types.h"
#include "topology/SparseGridLevels.h"
#include "topology/TopologyTypes.h"

namespace stroma::sparsegrid {

/// A triangle surface. Indices must be valid for `points` (checked by buildSparseGrid).
struct Surface {
  std::span<const Vec3d> points;
  std::span<const Triangle> triangles;
};

/// About how many bytes buildSparseGrid() allocates for a box of `cells` cells per axis (given as
/// reals, so that a size too large for the integer types can be estimated and refused).
double estimateBuildBytes(const std::array<double, 3>& cells, int samples);

/// Classifies the cells of `box` around `surface` and keeps the non-empty ones (see the file
/// comment). `samples` (1 to 16) sub-cells per axis measure the boundary cells' fractions.
/// Returns false, with `error` saying why, for an index out of range of the points or a bad box.
bool buildSparseGrid(const Surface& surface, const GridBox& box, int samples, SparseGrid& grid,
                     std::string& error);

/// The next coarser level: cells grouped 2 x 2 x 2 (ceil(cells / 2) per axis, spacing doubled,
/// same origin; a box with an odd count grows by one fine cell). A coarse cell is kept when one
/// of its children is; it is full when its 8 children are, boundary otherwise; its fraction is
/// the mean of its children's (empty children count 0). When `children` is given, it receives
/// per coarse cell the index in `fine` of the child at each corner (child q at the corner q of
/// the coarse hexahedron, TopologyTypes.h order), kInvalidIndex for an empty child.
SparseGrid coarsenSparseGrid(const SparseGrid& fine,
                             std::vector<std::array<Index, 8>>* children = nullptr);

/// Fills `points` and `hexahedra` from `box` and `cells` (used by the two functions above).
void makeGridElements(SparseGrid& grid);

}  // namespace stroma::sparsegrid
