// SPDX-License-Identifier: MIT
// The element types of meshes: indices into the points of a topology, SOFA's vertex orders.
//
// Vertex order conventions (the same as SOFA's, Gmsh's and VTK's):
// - Tetrahedron (a, b, c, d) is positively oriented when (b - a) . ((c - a) x (d - a)) > 0,
//   that is when a, b, c turn counterclockwise seen from d. Every tetrahedron of SOFA's meshes
//   (mesh/liver.msh, cylinder.msh, torus_low_res.msh, ...) has this orientation.
// - Hexahedron: vertices 0 1 2 3 are the bottom face, counterclockwise seen from above, and
//   4 5 6 7 the top face above them: with local coordinates (u, v, w) in {0, 1}^3, vertex
//   0 (0,0,0), 1 (1,0,0), 2 (1,1,0), 3 (0,1,0), 4 (0,0,1), 5 (1,0,1), 6 (1,1,1), 7 (0,1,1).
//   RegularGridTopology numbers its hexahedra this way.
// - Triangles and quads are oriented by their vertex order (normal by the right-hand rule).
#pragma once

#include <array>
#include <cstdint>
#include <limits>

namespace stroma {

/// Index of a point (or of an element) in a topology.
using Index = std::uint32_t;
inline constexpr Index kInvalidIndex = std::numeric_limits<Index>::max();

using Edge = std::array<Index, 2>;
using Triangle = std::array<Index, 3>;
using Quad = std::array<Index, 4>;
using Tetrahedron = std::array<Index, 4>;
using Hexahedron = std::array<Index, 8>;

}  // namespace stroma
