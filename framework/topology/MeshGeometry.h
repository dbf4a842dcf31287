// SPDX-License-Identifier: MIT
// Geometry of mesh elements: signed volumes and quality checks (degenerate, inverted).
//
// Sign convention (TopologyTypes.h): a tetrahedron (a, b, c, d) is positive when
// V = (b - a) . ((c - a) x (d - a)) / 6 > 0, which is the orientation of every tetrahedron of
// SOFA's meshes. A hexahedron is positive when the Jacobian of its trilinear map is positive
// at each of its eight corners (vertex order of TopologyTypes.h).
//
// Quality classes, with L the longest edge of the element:
// - degenerate: |V| < tolerance * L^3 (flat, or two vertices at the same place: a finite
//   element computation would divide by zero). For a hexahedron, V is the smallest corner
//   volume |det J| / 6, so that a collapsed corner is caught.
// - inverted: not degenerate and V < 0 (for a hexahedron: some corner Jacobian < 0).
// A regular tetrahedron has V = L^3 / (6 sqrt 2) ~ 0.118 L^3; the default tolerance 1e-9 only
// flags elements that are flat up to rounding.
#pragma once

#include <span>
#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma {

inline constexpr double kDegenerateVolumeTolerance = 1e-9;

/// (b - a) . ((c - a) x (d - a)) / 6: positive for SOFA's vertex order.
inline double signedTetrahedronVolume(const Vec3d& a, const Vec3d& b, const Vec3d& c,
                                      const Vec3d& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

/// Signed volume of a tetrahedron of `points`. Indices must be valid.
double signedVolume(std::span<const Vec3d> points, const Tetrahedron& t);

/// Signed volume of a hexahedron of `points`: the sum of its six tetrahedra around the
/// diagonal 0-6, exact when its faces are planar. Indices must be valid.
double signedVolume(std::span<const Vec3d> points, const Hexahedron& h);

enum class ElementQuality { good, degenerate, inverted };

/// Longest edge of the element's bounding edges (the 6 edges of a tetrahedron, the 12 of a
/// hexahedron).
double longestEdge(std::span<const Vec3d> points, const Tetrahedron& t);
double longestEdge(std::span<const Vec3d> points, const Hexahedron& h);

ElementQuality tetrahedronQuality(std::span<const Vec3d> points, const Tetrahedron& t,
                                  double tolerance = kDegenerateVolumeTolerance);
ElementQuality hexahedronQuality(std::span<const Vec3d> points, const Hexahedron& h,
                                 double tolerance = kDegenerateVolumeTolerance);

/// Indices of the elements of each bad class, in increasing order. Elements with an index out
/// of range of `points` are skipped (reported separately).
struct QualityReport {
  std::vector<Index> degenerate;
  std::vector<Index> inverted;
  bool empty() const { return degenerate.empty() && inverted.empty(); }
};
QualityReport checkTetrahedra(std::span<const Vec3d> points,
                              std::span<const Tetrahedron> tetrahedra,
                              double tolerance = kDegenerateVolumeTolerance);
QualityReport checkHexahedra(std::span<const Vec3d> points, std::span<const Hexahedron> hexahedra,
                             double tolerance = kDegenerateVolumeTolerance);

/// Indices of the elements that use a point index >= nbPoints.
template <std::size_t N>
std::vector<Index> findIndicesOutOfRange(std::span<const std::array<Index, N>> elements,
                                         std::size_t nbPoints) {
  std::vector<Index> bad;
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (Index v : elements[e])
      if (v >= nbPoints) {
        bad.push_back(static_cast<Index>(e));
        break;
      }
  return bad;
}

}  // namespace stroma
