// SPDX-License-Identifier: MIT
// Closed triangle surfaces for the sparse-grid tests: an axis-aligned box and an icosphere, with
// the exact volume they enclose, and an OBJ writer.
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

struct TriangleSurface {
  std::vector<Vec3d> points;
  std::vector<Triangle> triangles;

  /// The enclosed volume (divergence theorem; positive for outward triangles).
  double volume() const {
    double v = 0;
    for (const Triangle& t : triangles) v += points[t[0]].dot(points[t[1]].cross(points[t[2]])) / 6;
    return v;
  }
  /// Every triangle reversed (an inside-out surface).
  TriangleSurface flipped() const {
    TriangleSurface s = *this;
    for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
    return s;
  }
  std::string obj() const {
    std::string text = "# written by the sparse-grid tests\n";
    char line[128];
    for (const Vec3d& p : points) {
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
      text += line;
    }
    for (const Triangle& t : triangles)
      text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
              std::to_string(t[2] + 1) + "\n";
    return text;
  }
};

/// The surface of the box [lo, hi], 12 triangles oriented outwards.
inline TriangleSurface boxSurface(const Vec3d& lo, const Vec3d& hi) {
  TriangleSurface s;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        s.points.push_back(Vec3d(i ? hi.x() : lo.x(), j ? hi.y() : lo.y(), k ? hi.z() : lo.z()));
  // Points: bit 0 x, bit 1 y, bit 2 z. Each face as a quad seen from outside, counterclockwise.
  const std::array<std::array<Index, 4>, 6> faces{
      {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& f : faces) {
    s.triangles.push_back({f[0], f[1], f[2]});
    s.triangles.push_back({f[0], f[2], f[3]});
  }
  return s;
}

/// An icosahedron subdivided `levels` times, its points on the sphere (centre, radius).
inline TriangleSurface icosphere(int levels, const Vec3d& centre = Vec3d::Zero(),
                                 double radius = 1.0) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriangleSurface s;
  s.points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3d& p : s.points) p.normalize();
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<Index, Index>, Index> middles;
    auto middle = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      auto [it, added] = middles.try_emplace({key.first, key.second}, Index(s.points.size()));
      if (added) s.points.push_back((s.points[a] + s.points[b]).normalized());
      return it->second;
    };
    std::vector<Triangle> finer;
    for (const Triangle& tr : s.triangles) {
      const Index ab = middle(tr[0], tr[1]), bc = middle(tr[1], tr[2]), ca = middle(tr[2], tr[0]);
      finer.push_back({tr[0], ab, ca});
      finer.push_back({tr[1], bc, ab});
      finer.push_back({tr[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    s.triangles = std::move(finer);
  }
  if (s.volume() < 0) s = s.flipped();  // outwards
  for (Vec3d& p : s.points) p = centre + radius * p;
  return s;
}

}  // namespace stroma::test
