// SPDX-License-Identifier: MIT
#include "PrimitiveMeshes.h"

#include <cmath>

namespace stroma {

PrimitiveMesh boxMesh(const Vec3d& size) {
  PrimitiveMesh m;
  const Vec3d h = 0.5 * size;
  for (int k = 0; k < 8; ++k)
    m.points.emplace_back((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(),
                          (k & 4) ? h.z() : -h.z());
  // Each face as a quad of corner numbers (bit 0: +x, bit 1: +y, bit 2: +z), counterclockwise
  // seen from outside, split along its first diagonal.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    m.triangles.emplace_back(f[0], f[1], f[2]);
    m.triangles.emplace_back(f[0], f[2], f[3]);
  }
  return m;
}

PrimitiveMesh cylinderMesh(double radius, double length, int segments) {
  PrimitiveMesh m;
  const double h = 0.5 * length;
  for (int side = 0; side < 2; ++side)
    for (int k = 0; k < segments; ++k) {
      const double a = 2 * M_PI * k / segments;
      m.points.emplace_back(radius * std::cos(a), radius * std::sin(a), side ? h : -h);
    }
  const int bottom = 2 * segments, top = bottom + 1;
  m.points.emplace_back(0, 0, -h);
  m.points.emplace_back(0, 0, h);
  for (int k = 0; k < segments; ++k) {
    const int next = (k + 1) % segments;
    m.triangles.emplace_back(k, next, segments + next);
    m.triangles.emplace_back(k, segments + next, segments + k);
    m.triangles.emplace_back(bottom, next, k);
    m.triangles.emplace_back(top, segments + k, segments + next);
  }
  return m;
}

PrimitiveMesh sphereMesh(double radius, int rings, int segments) {
  PrimitiveMesh m;
  m.points.emplace_back(0, 0, -radius);  // south pole
  for (int r = 1; r < rings; ++r) {
    const double polar = M_PI * r / rings;  // from the south pole
    for (int k = 0; k < segments; ++k) {
      const double a = 2 * M_PI * k / segments;
      m.points.emplace_back(radius * std::sin(polar) * std::cos(a),
                            radius * std::sin(polar) * std::sin(a), -radius * std::cos(polar));
    }
  }
  const int north = static_cast<int>(m.points.size());
  m.points.emplace_back(0, 0, radius);
  const auto at = [&](int ring, int k) { return 1 + (ring - 1) * segments + k % segments; };
  for (int k = 0; k < segments; ++k) {
    m.triangles.emplace_back(0, at(1, k + 1), at(1, k));
    for (int r = 1; r + 1 < rings; ++r) {
      m.triangles.emplace_back(at(r, k), at(r, k + 1), at(r + 1, k + 1));
      m.triangles.emplace_back(at(r, k), at(r + 1, k + 1), at(r + 1, k));
    }
    m.triangles.emplace_back(north, at(rings - 1, k), at(rings - 1, k + 1));
  }
  return m;
}

void transformMesh(PrimitiveMesh& mesh, const RigidCoord3& frame) {
  for (Vec3d& p : mesh.points) p = frame.center + frame.orientation * p;
}

}  // namespace stroma
