// SPDX-License-Identifier: MIT
// The exact proximity primitives of collision detection: the closest point of a triangle or a
// segment to a point, the closest points of two segments, and the axis-aligned box that bounds
// every collision primitive. Free functions on Eigen vectors; they know nothing of components,
// states or trees.
//
// Each query returns a point (or two) lying on the primitive by construction (its parameters are
// clamped to the primitive's domain), and distance = |difference of the returned points|,
// computed from those points. Every input that is finite gives a finite answer, degenerate
// primitives included (zero-length segments, parallel or collinear segments, triangles of zero
// area); the per-case formulas are given with each function. Inputs that are not finite (NaN,
// infinity) are outside the contract.
//
// References: C. Ericson, "Real-Time Collision Detection", Morgan Kaufmann 2005, sections 5.1.2
// (closest point on a segment), 5.1.5 (closest point on a triangle, its Voronoi regions) and
// 5.1.9 (closest points of two segments); V. Lumelsky, "On fast computation of distance between
// line segments", Information Processing Letters 21 (1985) 55-61. The formulations here are
// written from the minimisation problems themselves; see plugins/Collision/README.md.
#pragma once

#include <limits>

#include "collision/Aabb.h"
#include "core/Types.h"

namespace stroma::collision {

/// Closest point of the triangle (a, b, c) to p.
///   closest  = barycentric[0] a + barycentric[1] b + barycentric[2] c, with every coordinate
///              >= 0 and their sum 1 (to rounding);
///   distance = |p - closest| >= 0.
struct PointTriangleResult {
  Vec3d closest;
  Vec3d barycentric;
  double distance;
};

/// The closest point of the filled triangle (a, b, c) to p: the minimiser of |p - x| over
/// x = u a + v b + w c, u + v + w = 1, u, v, w >= 0 (Ericson 2005, section 5.1.5).
///
/// Written for the vertices renamed (i, j, k), a rotation of (a, b, c) such that i -> j is the
/// longest edge, with e = vj - vi, f = vk - vi and n = e x f (the result does not depend on the
/// order or orientation of the vertices):
/// - Face: the foot x = vi + bj e + bk f of p on the plane has
///     bk = (e x (p - vi)).n / n.n,   bj = ((p - vi).e - bk f.e) / e.e,   bi = 1 - bj - bk,
///   (bj from (x - vi).e = (p - vi).e); when all three are >= 0 the foot is the answer, at
///   distance the height of p over the plane. Taking bj from the projection on the longest edge
///   rather than from its own signed volume matters for thin triangles: the rounding of n is then
///   mostly a turn about that edge, and the foot keeps the exact position of p along it whatever
///   the rounding of bk, so the error stays at rounding level for any shape (measured under
///   4e-16 times the coordinates' size, slivers of every relative height included).
/// - Outside: a coordinate is negative. The closest point then lies on an edge whose opposite
///   coordinate is negative (an edge that faces p in the plane; a point of a vertex's normal
///   cone is on the outer side of one of the vertex's two edges), so the answer is the nearer of
///   the closest points on those one or two edges (closestPointOnSegment). This covers the three
///   edge regions and the three vertex regions of Ericson's seven Voronoi regions.
/// - Zero area: when the height over the longest edge is at most kDegenerateTriangle times that
///   edge (|n| <= kDegenerateTriangle |e|^2), the answer is the nearest of the closest points on
///   the three edges: for collinear vertices this is the closest point of the longest edge (the
///   edges cover the triangle), for two coincident vertices that of the remaining edge, and for
///   three coincident vertices the point itself with barycentric (1, 0, 0). The distance is then
///   over-estimated by at most the height, kDegenerateTriangle times the longest edge.
PointTriangleResult closestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b,
                                           const Vec3d& c);

/// Relative height (height over the longest edge / that edge) at or under which a triangle is
/// treated as flat. At this level n is rounding noise; the face formula stays accurate above it
/// and the flat treatment's error (the height) is at rounding level under it.
inline constexpr double kDegenerateTriangle = 1e-15;

/// Closest point of the segment [a, b] to p: closest = a + t (b - a), t in [0, 1] (closest is
/// exactly a at t = 0 and exactly b at t = 1); distance = |p - closest|.
struct PointSegmentResult {
  Vec3d closest;
  double t;
  double distance;
};

/// The closest point of [a, b] to p (Ericson 2005, section 5.1.2):
///   t = clamp((p - a).(b - a) / |b - a|^2, 0, 1).
/// A zero-length segment (|b - a|^2 == 0, which includes lengths whose square underflows) gives
/// t = 0, closest = a. Any other finite segment gives a finite t: the clamp absorbs the quotient
/// even when it overflows.
PointSegmentResult closestPointOnSegment(const Vec3d& p, const Vec3d& a, const Vec3d& b);

/// Closest points of the segments [p0, p1] and [q0, q1]:
///   closestOnFirst  = p0 + s (p1 - p0),   closestOnSecond = q0 + t (q1 - q0),   s, t in [0, 1],
///   distance = |closestOnFirst - closestOnSecond|.
/// When several pairs are closest (parallel overlapping segments) one of them is returned.
struct SegmentSegmentResult {
  Vec3d closestOnFirst, closestOnSecond;
  double s, t;
  double distance;
};

/// The closest points of two segments: the minimiser of f(s, t) = |p0 + s d1 - q0 - t d2|^2 over
/// the square [0, 1]^2, with d1 = p1 - p0, d2 = q1 - q0 (Ericson 2005, section 5.1.9; Lumelsky
/// 1985). f is a convex quadratic, so:
/// - Crossing lines: with n = d1 x d2 and r = q0 - p0, the closest points of the two lines are
///     s = (r x d2).n / n.n,  then t = (p0 + s d1 - q0).d2 / |d2|^2 (the best t for that s);
///   when both lie in [0, 1] they are the answer. Taking t from s rather than from its own
///   quotient keeps the pair on the valley of f, so that the rounding error of s for nearly
///   parallel lines moves the pair along the segments without changing the distance to first
///   order.
/// - Otherwise the minimum over the square lies on its boundary (s = 0, s = 1, t = 0 or t = 1),
///   and the answer is the nearest of the four point-segment queries: p0 and p1 against
///   [q0, q1], q0 and q1 against [p0, p1].
/// - Parallel lines (|n| <= kParallelSegments |d1| |d2|, the sine of their angle) use the
///   boundary alone: f is constant along the common direction, so one of its minimisers lies on
///   the boundary. This covers collinear overlapping segments (distance 0 at an endpoint of one
///   of them inside the other). For lines that meet inside both segments at an angle under the
///   threshold, the distance is over-estimated by at most kParallelSegments times half the
///   shorter segment, a rounding-level error.
/// - Zero-length segments: d1 = 0 gives s = 0 and the closest point of [q0, q1] to p0, d2 = 0
///   gives t = 0 and the closest point of [p0, p1] to q0, both give s = t = 0.
SegmentSegmentResult closestPointsOfSegments(const Vec3d& p0, const Vec3d& p1, const Vec3d& q0,
                                             const Vec3d& q1);

/// Sine of the angle at or under which two segments are treated as parallel (see
/// closestPointsOfSegments): at this level n is rounding noise. Above it the crossing-line
/// formula is accurate (measured under 4e-16 times the coordinates' size at every angle).
inline constexpr double kParallelSegments = 1e-15;

/// The box type of every collision primitive and tree: stroma::Aabb (framework/collision/Aabb.h).
using stroma::Aabb;
/// a.overlaps(b), as a free function for generic code (the trees' brute-force references).
inline bool overlaps(const Aabb& a, const Aabb& b) { return a.overlaps(b); }

}  // namespace stroma::collision
