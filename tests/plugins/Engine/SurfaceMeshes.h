// SPDX-License-Identifier: MIT
// Closed triangle surfaces with known mass properties, for the tests of GenerateRigidMass and
// its kernel: an axis-aligned box and a geodesic sphere (subdivided icosahedron), both with
// their faces oriented outwards.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma::test {

struct Surface {
  std::vector<Vec3d> points;
  std::vector<Triangle> triangles;
  std::vector<Quad> quads;
};

/// The box [0, a] x [0, b] x [0, c]: point i + 2 j + 4 k at (i a, j b, k c); six outward quads,
/// or their 12 triangles (a b c), (a c d).
inline Surface boxSurface(double a, double b, double c, bool asQuads = false) {
  Surface s;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) s.points.emplace_back(i * a, j * b, k * c);
  const std::vector<Quad> faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  if (asQuads) {
    s.quads = faces;
  } else {
    for (const Quad& q : faces) {
      s.triangles.push_back({q[0], q[1], q[2]});
      s.triangles.push_back({q[0], q[2], q[3]});
    }
  }
  return s;
}

/// A geodesic sphere of radius r about the origin: the icosahedron with each triangle split
/// `level` times into 4, the new points pushed onto the sphere (20 * 4^level triangles).
inline Surface icosphere(int level, double r) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  Surface s;
  for (const Vec3d& p : {Vec3d(-1, t, 0), Vec3d(1, t, 0), Vec3d(-1, -t, 0), Vec3d(1, -t, 0),
                         Vec3d(0, -1, t), Vec3d(0, 1, t), Vec3d(0, -1, -t), Vec3d(0, 1, -t),
                         Vec3d(t, 0, -1), Vec3d(t, 0, 1), Vec3d(-t, 0, -1), Vec3d(-t, 0, 1)})
    s.points.push_back(r * p.normalized());
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<Index, Index>, Index> middles;
    auto middle = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = middles.try_emplace(key, static_cast<Index>(s.points.size()));
      if (added) s.points.push_back(r * (s.points[a] + s.points[b]).normalized());
      return it->second;
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : s.triangles) {
      const Index ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({ab, f[1], bc});
      finer.push_back({ca, bc, f[2]});
      finer.push_back({ab, bc, ca});
    }
    s.triangles = std::move(finer);
  }
  // Outwards: the normal along the direction from the center.
  for (Triangle& f : s.triangles) {
    const Vec3d &a = s.points[f[0]], &b = s.points[f[1]], &c = s.points[f[2]];
    if ((b - a).cross(c - a).dot(a + b + c) < 0) std::swap(f[1], f[2]);
  }
  return s;
}

/// Elements as a scene attribute: "0 1 2  0 2 3 ...".
template <class Element>
std::string elementsText(const std::vector<Element>& elements) {
  std::string text;
  for (const Element& e : elements)
    for (const Index i : e) text += std::to_string(i) + " ";
  return text;
}

inline std::string pointsText(const std::vector<Vec3d>& points) {
  std::string text;
  char buffer[96];
  for (const Vec3d& p : points) {
    std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g  ", p.x(), p.y(), p.z());
    text += buffer;
  }
  return text;
}

}  // namespace stroma::test
