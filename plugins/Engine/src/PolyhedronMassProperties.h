// SPDX-License-Identifier: MIT
// Mass properties of a solid given by its closed surface, free of components: volume, center
// of mass and inertia tensor, exact for the polyhedron that the triangles (and quads, split in
// two triangles) bound, by the divergence theorem over the faces.
//
// Formulas: D. Eberly, "Polyhedral Mass Properties (Revisited)", Geometric Tools, 2002 (rev.
// 2009), a simplification for triangular faces of B. Mirtich, "Fast and Accurate Computation
// of Polyhedral Mass Properties", Journal of Graphics Tools 1(2), 1996. The ten volume integrals
// of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx become sums over the faces of polynomials in their
// vertex coordinates (see PolyhedronMassProperties.cpp for the equations).
//
// Conventions: the faces are oriented outwards (counter-clockwise seen from outside), as the
// mesh loaders give a closed surface; inwards faces give a negative volume. The surface must be
// closed: every edge run by as many faces in one direction as in the other (checked by
// findUnmatchedEdge). The results are for unit density; multiply by the density.
// Numerical note: the integrals are taken about the first point of the first face, not the
// world origin, so that a body far from the origin keeps its accuracy (the second moments
// about the origin would cancel in c^2 terms); the inertia is then moved to the center of mass.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma {

/// Volume, center of mass and inertia of a homogeneous solid of unit density.
struct PolyhedronMassProperties {
  double volume = 0;             ///< V (m^3); negative when the faces point inwards
  Vec3d center = Vec3d::Zero();  ///< center of mass c = (1/V) integral of x (m)
  /// Inertia tensor about the center of mass, world axes, unit density (m^5): the integral of
  /// |r|^2 I - r r^T over the solid, r = x - c. Divided by V, the inertia per unit mass (m^2).
  Mat3d inertia = Mat3d::Zero();
};

/// Integrates over the triangles and the quads (a quad (a, b, c, d) as the triangles (a, b, c)
/// and (a, c, d)). Precondition: every index is below positions.size(). Any surface gives a
/// result; it is the solid's only when the surface is closed (findUnmatchedEdge) and the volume
/// positive. Cost: O(number of faces), no allocation.
PolyhedronMassProperties computePolyhedronMassProperties(std::span<const Vec3d> positions,
                                                         std::span<const Triangle> triangles,
                                                         std::span<const Quad> quads);

/// An edge of a surface that no face runs the other way, and the face (the first that runs it
/// in the direction in excess).
struct UnmatchedEdge {
  Index from = 0, to = 0;  ///< the edge as the face runs it (the face's own point indices)
  std::size_t face = 0;    ///< index in the triangles, or in the quads when `inQuad`
  bool inQuad = false;
};

/// The first edge (in the order of the sorted point pairs) that the faces run more often in one
/// direction than in the other: a hole in the surface, or a face oriented against its
/// neighbours. None for a closed, consistently oriented surface. Points at the same position
/// count as one (an OBJ file read with its texture seams duplicates points along them, and the
/// surface is still closed); non-manifold edges are allowed when they balance (two cubes
/// sharing an edge); degenerate edges (a, a) are ignored. Preconditions: every index is below
/// positions.size(), every position finite. Cost: O((P + E) log(P + E)) for P points and E face
/// edges.
std::optional<UnmatchedEdge> findUnmatchedEdge(std::span<const Vec3d> positions,
                                               std::span<const Triangle> triangles,
                                               std::span<const Quad> quads);

}  // namespace stroma
