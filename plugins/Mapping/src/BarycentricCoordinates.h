// SPDX-License-Identifier: MIT
// Where points lie in a volume mesh: barycentric coordinates in tetrahedra, trilinear coordinates
// in hexahedra, and the element of each point (the one containing it, else the nearest). The
// kernel of BarycentricMapping; it knows nothing of states or components.
//
// Tetrahedron (x0..x3): p = sum w_i x_i with sum w_i = 1; w solves
//   [x1 - x0, x2 - x0, x3 - x0] (w1, w2, w3)^T = p - x0,  w0 = 1 - w1 - w2 - w3.
// Hexahedron (x0..x7, vertex order of topology/TopologyTypes.h: vertex i at local corner
// (u_i, v_i, w_i) in {0,1}^3): p = sum N_i(u, v, w) x_i with the trilinear shape functions
//   N_i = (u_i u + (1 - u_i)(1 - u)) (v_i v + (1 - v_i)(1 - v)) (w_i w + (1 - w_i)(1 - w)),
// inverted by Newton's method (exact in one step for a parallelepiped, such as a regular grid's
// cell). Both are linear interpolations: a field linear in space is reproduced exactly, the
// weights lie in [0, 1] and sum to 1 inside the element (Zienkiewicz & Taylor, The Finite Element
// Method vol. 1, 7th ed., 2013, sections 6.3 and 6.5).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma::barycentric {

/// Weights of p in a tetrahedron; false when it is degenerate (no volume).
bool tetrahedronWeights(const std::array<Vec3d, 4>& x, const Vec3d& p, std::array<double, 4>& w);

/// Local coordinates (u, v, w) of p in a hexahedron; false when Newton's method fails
/// (degenerate element, or p far outside a distorted one).
bool hexahedronCoordinates(const std::array<Vec3d, 8>& x, const Vec3d& p, Vec3d& uvw);

/// The 8 trilinear shape functions at local coordinates (u, v, w).
std::array<double, 8> hexahedronWeights(const Vec3d& uvw);

/// A point embedded in an element: p = sum weights[k] x[nodes[k]], k < count (4 or 8).
struct EmbeddedPoint {
  std::array<Index, 8> nodes{};
  std::array<double, 8> weights{};
  int count = 0;
  /// The element, among the tetrahedra then the hexahedra (hexahedron h is tetrahedra.size()+h).
  Index element = kInvalidIndex;
  /// 0 for a point inside its element; else its distance to it (exact for a tetrahedron; for
  /// a hexahedron, the distance to its point at the local coordinates clamped to [0, 1]^3,
  /// exact for a box and an upper bound otherwise).
  double distance = 0;
};

/// Embeds each point in the element of the mesh that contains it (within a relative tolerance
/// of 1e-10 in local coordinates), else in the nearest element, whose coordinates then
/// extrapolate (some weights are negative). Elements are looked up in a uniform grid of their
/// bounding boxes, so that the cost is about linear in the number of points and elements.
/// `degenerate` receives the elements that could not be used (no volume).
std::vector<EmbeddedPoint> embedPoints(const std::vector<Vec3d>& nodes,
                                       const std::vector<Tetrahedron>& tetrahedra,
                                       const std::vector<Hexahedron>& hexahedra,
                                       const std::vector<Vec3d>& points,
                                       std::vector<Index>* degenerate = nullptr);

}  // namespace stroma::barycentric
