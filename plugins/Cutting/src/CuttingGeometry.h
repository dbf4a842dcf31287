// SPDX-License-Identifier: MIT
// Intersection tests between a cutting tool and tetrahedra: a point, a segment or a triangle
// (the surface a segment sweeps during a step, as two triangles) against a tetrahedron. Closed
// sets: touching counts as crossing. Knows nothing of components.
//
// A triangle meets a tetrahedron iff one of the triangle's edges meets the tetrahedron (an end
// inside, or the edge crossing a face) or one of the tetrahedron's edges crosses the triangle:
// their intersection is a convex polygon, and each of its vertices is of one of these kinds
// (Ericson, Real-Time Collision Detection, 2005, section 5.3 for the segment-triangle test).
#pragma once

#include <array>

#include "core/Types.h"

namespace stroma::cutting {

using TetrahedronPoints = std::array<Vec3d, 4>;

/// True when p lies in the tetrahedron (or on its boundary, within a relative 1e-12).
bool pointInTetrahedron(const Vec3d& p, const TetrahedronPoints& x);

/// True when the segment [p, q] meets the triangle (a, b, c).
bool segmentMeetsTriangle(const Vec3d& p, const Vec3d& q, const Vec3d& a, const Vec3d& b,
                          const Vec3d& c);

/// True when the segment [p, q] meets the tetrahedron.
bool segmentMeetsTetrahedron(const Vec3d& p, const Vec3d& q, const TetrahedronPoints& x);

/// True when the triangle (a, b, c) meets the tetrahedron. A degenerate triangle (no area) is
/// tested as its longest side.
bool triangleMeetsTetrahedron(const Vec3d& a, const Vec3d& b, const Vec3d& c,
                              const TetrahedronPoints& x);

}  // namespace stroma::cutting
