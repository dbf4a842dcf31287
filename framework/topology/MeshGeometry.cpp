// SPDX-License-Identifier: MIT
#include "topology/MeshGeometry.h"

#include <algorithm>
#include <cmath>

#include "topology/MeshAdjacency.h"

namespace stroma {

namespace {

/// Vertex of a hexahedron at local coordinates (u, v, w) in {0, 1}^3 (TopologyTypes.h).
constexpr int hexVertex(int u, int v, int w) {
  constexpr int bottom[2][2] = {{0, 3}, {1, 2}};  // [u][v]
  return bottom[u][v] + 4 * w;
}

bool inRange(std::span<const Vec3d> points, const auto& element) {
  for (Index v : element)
    if (v >= points.size()) return false;
  return true;
}

}  // namespace

double signedVolume(std::span<const Vec3d> points, const Tetrahedron& t) {
  return signedTetrahedronVolume(points[t[0]], points[t[1]], points[t[2]], points[t[3]]);
}

double signedVolume(std::span<const Vec3d> points, const Hexahedron& h) {
  // Six tetrahedra around the diagonal 0-6, each a path 0 -> one axis -> two axes -> 6.
  constexpr int paths[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                               {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  double volume = 0;
  for (const auto& p : paths)
    volume +=
        signedTetrahedronVolume(points[h[p[0]]], points[h[p[1]]], points[h[p[2]]], points[h[p[3]]]);
  return volume;
}

double longestEdge(std::span<const Vec3d> points, const Tetrahedron& t) {
  double longest = 0;
  for (const auto& e : kTetrahedronEdges)
    longest = std::max(longest, (points[t[e[1]]] - points[t[e[0]]]).norm());
  return longest;
}

double longestEdge(std::span<const Vec3d> points, const Hexahedron& h) {
  double longest = 0;
  for (const auto& e : kHexahedronEdges)
    longest = std::max(longest, (points[h[e[1]]] - points[h[e[0]]]).norm());
  return longest;
}

ElementQuality tetrahedronQuality(std::span<const Vec3d> points, const Tetrahedron& t,
                                  double tolerance) {
  const double volume = signedVolume(points, t);
  const double l = longestEdge(points, t);
  if (!(std::abs(volume) >= tolerance * l * l * l) || l == 0) return ElementQuality::degenerate;
  return volume < 0 ? ElementQuality::inverted : ElementQuality::good;
}

ElementQuality hexahedronQuality(std::span<const Vec3d> points, const Hexahedron& h,
                                 double tolerance) {
  const double l = longestEdge(points, h);
  if (!(l > 0)) return ElementQuality::degenerate;
  double smallest = HUGE_VAL;
  bool negative = false;
  for (int u = 0; u < 2; ++u)
    for (int v = 0; v < 2; ++v)
      for (int w = 0; w < 2; ++w) {
        // Jacobian columns at this corner: the edges along u, v and w, from 0 to 1.
        const Vec3d du = points[h[hexVertex(1, v, w)]] - points[h[hexVertex(0, v, w)]];
        const Vec3d dv = points[h[hexVertex(u, 1, w)]] - points[h[hexVertex(u, 0, w)]];
        const Vec3d dw = points[h[hexVertex(u, v, 1)]] - points[h[hexVertex(u, v, 0)]];
        const double corner = du.dot(dv.cross(dw)) / 6.0;
        smallest = std::min(smallest, std::abs(corner));
        negative |= corner < 0;
      }
  if (!(smallest >= tolerance * l * l * l)) return ElementQuality::degenerate;
  return negative ? ElementQuality::inverted : ElementQuality::good;
}

QualityReport checkTetrahedra(std::span<const Vec3d> points,
                              std::span<const Tetrahedron> tetrahedra, double tolerance) {
  QualityReport report;
  for (std::size_t i = 0; i < tetrahedra.size(); ++i) {
    if (!inRange(points, tetrahedra[i])) continue;
    switch (tetrahedronQuality(points, tetrahedra[i], tolerance)) {
      case ElementQuality::degenerate:
        report.degenerate.push_back(static_cast<Index>(i));
        break;
      case ElementQuality::inverted:
        report.inverted.push_back(static_cast<Index>(i));
        break;
      case ElementQuality::good:
        break;
    }
  }
  return report;
}

QualityReport checkHexahedra(std::span<const Vec3d> points, std::span<const Hexahedron> hexahedra,
                             double tolerance) {
  QualityReport report;
  for (std::size_t i = 0; i < hexahedra.size(); ++i) {
    if (!inRange(points, hexahedra[i])) continue;
    switch (hexahedronQuality(points, hexahedra[i], tolerance)) {
      case ElementQuality::degenerate:
        report.degenerate.push_back(static_cast<Index>(i));
        break;
      case ElementQuality::inverted:
        report.inverted.push_back(static_cast<Index>(i));
        break;
      case ElementQuality::good:
        break;
    }
  }
  return report;
}

}  // namespace stroma
