// SPDX-License-Identifier: MIT
#include "CuttingGeometry.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "topology/MeshAdjacency.h"

namespace stroma::cutting {

bool pointInTetrahedron(const Vec3d& p, const TetrahedronPoints& x) {
  Mat3d edges;
  edges << x[1] - x[0], x[2] - x[0], x[3] - x[0];
  const double volume6 = edges.determinant();
  if (volume6 == 0) return false;
  const Vec3d w = edges.inverse() * (p - x[0]);  // barycentric weights of x1, x2, x3
  const double tolerance = -1e-12;
  return w.x() >= tolerance && w.y() >= tolerance && w.z() >= tolerance && 1 - w.sum() >= tolerance;
}

bool segmentMeetsTriangle(const Vec3d& p, const Vec3d& q, const Vec3d& a, const Vec3d& b,
                          const Vec3d& c) {
  // Solve p + s (q - p) = a + u (b - a) + v (c - a) with s, u, v, 1 - u - v in [0, 1]
  // (Ericson 2005, section 5.3.6, by Cramer's rule).
  const Vec3d ab = b - a, ac = c - a, qp = p - q;
  const Vec3d n = ab.cross(ac);
  const double d = qp.dot(n);
  const double scale = ab.norm() * ac.norm() * qp.norm();
  if (std::abs(d) <= 1e-14 * scale) return false;  // parallel (coplanar cases: the edges)
  const Vec3d ap = p - a;
  double s = ap.dot(n) / d;
  const Vec3d e = qp.cross(ap);
  double u = ac.dot(e) / d;
  double v = -ab.dot(e) / d;
  const double eps = 1e-12;
  return s >= -eps && s <= 1 + eps && u >= -eps && v >= -eps && u + v <= 1 + eps;
}

bool segmentMeetsTetrahedron(const Vec3d& p, const Vec3d& q, const TetrahedronPoints& x) {
  if (pointInTetrahedron(p, x) || pointInTetrahedron(q, x)) return true;
  for (const auto& f : kTetrahedronFaces)
    if (segmentMeetsTriangle(p, q, x[f[0]], x[f[1]], x[f[2]])) return true;
  return false;
}

bool triangleMeetsTetrahedron(const Vec3d& a, const Vec3d& b, const Vec3d& c,
                              const TetrahedronPoints& x) {
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
  const double longest = std::max({ab, bc, ca});
  if ((b - a).cross(c - a).norm() <= 1e-12 * longest * longest) {
    if (longest == ab) return segmentMeetsTetrahedron(a, b, x);
    if (longest == bc) return segmentMeetsTetrahedron(b, c, x);
    return segmentMeetsTetrahedron(c, a, x);
  }
  if (segmentMeetsTetrahedron(a, b, x) || segmentMeetsTetrahedron(b, c, x) ||
      segmentMeetsTetrahedron(c, a, x))
    return true;
  for (const auto& e : kTetrahedronEdges)
    if (segmentMeetsTriangle(x[e[0]], x[e[1]], a, b, c)) return true;
  return false;
}

}  // namespace stroma::cutting
