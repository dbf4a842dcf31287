// SPDX-License-Identifier: MIT
// A regular grid of nx x ny x nz points, SOFA's numbering: point (i, j, k) is
// i + nx (j + ny k); hexahedron (i, j, k) is i + (nx-1) (j + (ny-1) k), with its vertices
// (i,j,k) (i+1,j,k) (i+1,j+1,k) (i,j+1,k) then the same at k+1 (TopologyTypes.h order).
#pragma once

#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma {

struct GridSize {
  int nx = 2, ny = 2, nz = 2;  ///< points per axis (>= 1)
  std::size_t points() const { return std::size_t(nx) * ny * nz; }
  Index point(int i, int j, int k) const { return Index(i + nx * (j + ny * k)); }
};

/// Points origin + (i dx, j dy, k dz).
std::vector<Vec3d> makeGridPoints(const GridSize& n, const Vec3d& origin, const Vec3d& spacing);
/// The (nx-1)(ny-1)(nz-1) hexahedra, x fastest.
std::vector<Hexahedron> makeGridHexahedra(const GridSize& n);
/// Every quad of the grid lines (inside ones too): those in xy planes, then xz, then yz.
std::vector<Quad> makeGridQuads(const GridSize& n);
/// Every grid segment: along x, then y, then z.
std::vector<Edge> makeGridEdges(const GridSize& n);

}  // namespace stroma
