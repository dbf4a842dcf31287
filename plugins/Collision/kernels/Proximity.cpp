// SPDX-License-Identifier: MIT
#include "Collision/kernels/Proximity.h"

#include <algorithm>

namespace stroma::collision {

PointSegmentResult closestPointOnSegment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d d = b - a;
  const double lengthSquared = d.squaredNorm();
  // Minimiser of |a + t d - p|^2 over the line, clamped to the segment. A zero-length segment is
  // its point a; otherwise the quotient is finite or +-infinity, and the clamp makes it finite.
  double t = 0;
  if (lengthSquared > 0) t = std::clamp((p - a).dot(d) / lengthSquared, 0.0, 1.0);
  PointSegmentResult r;
  r.t = t;
  r.closest = t == 0 ? a : t == 1 ? b : Vec3d(a + t * d);
  r.distance = (p - r.closest).norm();
  return r;
}

namespace {

// The closest point of the triangle's edge from vertex i to vertex j, as a triangle result.
PointTriangleResult closestPointOnEdge(const Vec3d& p, const Vec3d& vi, const Vec3d& vj, int i,
                                       int j) {
  const PointSegmentResult e = closestPointOnSegment(p, vi, vj);
  PointTriangleResult r;
  r.closest = e.closest;
  r.barycentric = Vec3d::Zero();
  r.barycentric[i] = 1 - e.t;
  r.barycentric[j] = e.t;
  r.distance = e.distance;
  return r;
}

// The nearer of two results (the first on a tie).
template <class Result>
Result nearer(const Result& first, const Result& second) {
  return second.distance < first.distance ? second : first;
}

}  // namespace

PointTriangleResult closestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b,
                                           const Vec3d& c) {
  // The vertices in the order (i, j, k) = (i, i + 1, i + 2) mod 3 that starts the longest edge.
  const Vec3d* const vertices[3] = {&a, &b, &c};
  const double lengths[3] = {(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()};
  const int i = int(std::max_element(lengths, lengths + 3) - lengths), j = (i + 1) % 3,
            k = (i + 2) % 3;
  const double longest = lengths[i];  // squared length of the edge from vertex i to vertex j
  const Vec3d& vi = *vertices[i];
  const Vec3d &vj = *vertices[j], &vk = *vertices[k];

  // Zero area (height over the longest edge <= kDegenerateTriangle times that edge): the
  // triangle is its edges.
  const Vec3d e = vj - vi, f = vk - vi, ip = p - vi;  // longest edge, other edge, point
  const Vec3d n = e.cross(f);
  const double nn = n.squaredNorm();
  if (nn <= kDegenerateTriangle * kDegenerateTriangle * longest * longest) {
    PointTriangleResult best = closestPointOnEdge(p, a, b, 0, 1);
    best = nearer(best, closestPointOnEdge(p, b, c, 1, 2));
    return nearer(best, closestPointOnEdge(p, c, a, 2, 0));
  }

  // Barycentric coordinates of the foot x = vi + bj e + bk f of p on the plane: bk from the
  // signed volumes, then bj from (x - vi).e = (p - vi).e, so that x has the projection of p on
  // the longest edge whatever the rounding of bk.
  const double bk = e.cross(ip).dot(n) / nn;
  const double bj = (ip.dot(e) - bk * f.dot(e)) / longest;
  const double bi = 1 - bj - bk;
  if (bi >= 0 && bj >= 0 && bk >= 0) {
    PointTriangleResult r;
    r.barycentric[i] = bi;
    r.barycentric[j] = bj;
    r.barycentric[k] = bk;
    // Exactly a vertex when the coordinates are a unit vector.
    r.closest = r.barycentric[0] * a + r.barycentric[1] * b + r.barycentric[2] * c;
    r.distance = (p - r.closest).norm();
    return r;
  }

  // Outside: the closest point is on an edge whose opposite coordinate is negative (one or two
  // edges).
  PointTriangleResult best{Vec3d::Zero(), Vec3d::Zero(), std::numeric_limits<double>::infinity()};
  if (bi < 0) best = nearer(best, closestPointOnEdge(p, vj, vk, j, k));
  if (bj < 0) best = nearer(best, closestPointOnEdge(p, vk, vi, k, i));
  if (bk < 0) best = nearer(best, closestPointOnEdge(p, vi, vj, i, j));
  return best;
}

SegmentSegmentResult closestPointsOfSegments(const Vec3d& p0, const Vec3d& p1, const Vec3d& q0,
                                             const Vec3d& q1) {
  const Vec3d d1 = p1 - p0, d2 = q1 - q0;
  const double length1 = d1.squaredNorm(), length2 = d2.squaredNorm();  // squared lengths

  // Zero-length segments: a point against a segment, or two points.
  if (length1 == 0 || length2 == 0) {
    SegmentSegmentResult r;
    if (length1 == 0) {
      const PointSegmentResult e = closestPointOnSegment(p0, q0, q1);
      r.s = 0;
      r.t = e.t;
      r.closestOnFirst = p0;
      r.closestOnSecond = e.closest;
    } else {
      const PointSegmentResult e = closestPointOnSegment(q0, p0, p1);
      r.s = e.t;
      r.t = 0;
      r.closestOnFirst = e.closest;
      r.closestOnSecond = q0;
    }
    r.distance = (r.closestOnFirst - r.closestOnSecond).norm();
    return r;
  }

  // Crossing lines: the closest points of the lines, s from the cross products and t the best
  // one for that s. Taken when both lie on the segments.
  const Vec3d n = d1.cross(d2);
  const double nn = n.squaredNorm();
  if (nn > kParallelSegments * kParallelSegments * length1 * length2) {
    const double s = (q0 - p0).cross(d2).dot(n) / nn;
    if (s >= 0 && s <= 1) {
      const Vec3d onFirst = p0 + s * d1;
      const double t = (onFirst - q0).dot(d2) / length2;
      if (t >= 0 && t <= 1) {
        SegmentSegmentResult r;
        r.s = s;
        r.t = t;
        r.closestOnFirst = onFirst;
        r.closestOnSecond = q0 + t * d2;
        r.distance = (r.closestOnFirst - r.closestOnSecond).norm();
        return r;
      }
    }
  }

  // On the boundary of [0, 1]^2 (also for parallel lines): the nearest of the four endpoint
  // queries.
  const auto fromFirstEnd = [&](const Vec3d& end, double s) {
    const PointSegmentResult e = closestPointOnSegment(end, q0, q1);
    return SegmentSegmentResult{end, e.closest, s, e.t, e.distance};
  };
  const auto fromSecondEnd = [&](const Vec3d& end, double t) {
    const PointSegmentResult e = closestPointOnSegment(end, p0, p1);
    return SegmentSegmentResult{e.closest, end, e.t, t, e.distance};
  };
  return nearer(nearer(fromFirstEnd(p0, 0), fromFirstEnd(p1, 1)),
                nearer(fromSecondEnd(q0, 0), fromSecondEnd(q1, 1)));
}

}  // namespace stroma::collision
