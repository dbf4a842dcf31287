// SPDX-License-Identifier: MIT
// Does a triangle overlap an axis-aligned box? The separating axis theorem on the 13 axes that
// can separate a triangle from a box (Akenine-Moller 2001, "Fast 3D triangle-box overlap
// testing", J. Graphics Tools 6(1)): the 3 box face normals, the triangle's normal, and the 9
// cross products of a box axis with a triangle edge. The box is closed: a triangle that only
// touches it overlaps it. Degenerate triangles (segments, points) are handled: their zero
// axes separate nothing and the other axes decide.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/Types.h"

namespace stroma::sparsegrid {

/// True when triangle (a, b, c) and the box of centre `centre` and half sizes `half` (each
/// >= 0) share at least a point.
inline bool triangleOverlapsBox(const Vec3d& centre, const Vec3d& half, const Vec3d& a,
                                const Vec3d& b, const Vec3d& c) {
  // Work in the box's frame.
  const Vec3d v0 = a - centre, v1 = b - centre, v2 = c - centre;

  // Box face normals: the triangle's bounding box against the box.
  for (int k = 0; k < 3; ++k) {
    if (std::min({v0[k], v1[k], v2[k]}) > half[k]) return false;
    if (std::max({v0[k], v1[k], v2[k]}) < -half[k]) return false;
  }

  // The nine axes e_k x edge: with a = e_k x e, a . v needs only two coordinates.
  const Vec3d edges[3] = {v1 - v0, v2 - v1, v0 - v2};
  for (const Vec3d& e : edges) {
    const Vec3d axes[3] = {Vec3d(0, -e.z(), e.y()), Vec3d(e.z(), 0, -e.x()),
                           Vec3d(-e.y(), e.x(), 0)};
    for (const Vec3d& axis : axes) {
      const double p0 = axis.dot(v0), p1 = axis.dot(v1), p2 = axis.dot(v2);
      const double r = half.x() * std::abs(axis.x()) + half.y() * std::abs(axis.y()) +
                       half.z() * std::abs(axis.z());
      if (std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r) return false;
    }
  }

  // The triangle's plane: the box's projection on the normal must reach the plane.
  const Vec3d normal = edges[0].cross(edges[1]);
  const double r = half.x() * std::abs(normal.x()) + half.y() * std::abs(normal.y()) +
                   half.z() * std::abs(normal.z());
  return std::abs(normal.dot(v0)) <= r;
}

}  // namespace stroma::sparsegrid
