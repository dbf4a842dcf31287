// SPDX-License-Identifier: MIT
#include "PolyhedronMassProperties.h"

#include <algorithm>
#include <tuple>
#include <vector>

namespace stroma {

namespace {

/// Eberly (2002), section 2: for one coordinate w of a triangle's vertices w0, w1, w2,
///   f1 = w0 + w1 + w2,
///   f2 = w0^2 + w0 w1 + w1^2 + w2 f1                    (every monomial of degree 2),
///   f3 = w0^3 + w0^2 w1 + w0 w1^2 + w1^3 + w2 f2        (every monomial of degree 3),
///   g_i = f2 + w_i (f1 + w_i).
struct CoordinateSums {
  double f1, f2, f3;
  Vec3d g;
};

CoordinateSums coordinateSums(double w0, double w1, double w2) {
  CoordinateSums s;
  s.f1 = w0 + w1 + w2;
  s.f2 = w0 * w0 + w0 * w1 + w1 * w1 + w2 * s.f1;
  s.f3 = w0 * w0 * w0 + w0 * w0 * w1 + w0 * w1 * w1 + w1 * w1 * w1 + w2 * s.f2;
  s.g = Vec3d(s.f2 + w0 * (s.f1 + w0), s.f2 + w1 * (s.f1 + w1), s.f2 + w2 * (s.f1 + w2));
  return s;
}

/// The face sums of the ten volume integrals, before their constant factors. With the
/// unnormalized face normal N = (p1 - p0) x (p2 - p0), the divergence theorem gives (Eberly
/// 2002, section 2, from Mirtich 1996):
///   int 1 = sum N_x f1(x) / 6,
///   int x = sum N_x f2(x) / 24            (and y, z with N_y f2(y), N_z f2(z)),
///   int x^2 = sum N_x f3(x) / 60          (and y^2, z^2),
///   int xy = sum N_x (y0 g0(x) + y1 g1(x) + y2 g2(x)) / 120
///                                         (yz from N_y, g(y) and z; zx from N_z, g(z) and x).
struct FaceSums {
  double volume = 0;
  Vec3d first = Vec3d::Zero();     // x, y, z
  Vec3d squares = Vec3d::Zero();   // x^2, y^2, z^2
  Vec3d products = Vec3d::Zero();  // xy, yz, zx

  void addTriangle(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2) {
    const Vec3d n = (p1 - p0).cross(p2 - p0);
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;  // the products pair each axis with the next: xy, yz, zx
      const CoordinateSums s = coordinateSums(p0[a], p1[a], p2[a]);
      if (a == 0) volume += n[0] * s.f1;
      first[a] += n[a] * s.f2;
      squares[a] += n[a] * s.f3;
      products[a] += n[a] * (p0[b] * s.g[0] + p1[b] * s.g[1] + p2[b] * s.g[2]);
    }
  }
};

}  // namespace

PolyhedronMassProperties computePolyhedronMassProperties(std::span<const Vec3d> positions,
                                                         std::span<const Triangle> triangles,
                                                         std::span<const Quad> quads) {
  PolyhedronMassProperties result;
  if (triangles.empty() && quads.empty()) return result;
  // Integrate about a point of the surface (see the header's numerical note).
  const Vec3d origin = positions[triangles.empty() ? quads[0][0] : triangles[0][0]];
  FaceSums sums;
  for (const Triangle& t : triangles)
    sums.addTriangle(positions[t[0]] - origin, positions[t[1]] - origin, positions[t[2]] - origin);
  for (const Quad& q : quads) {
    const Vec3d p0 = positions[q[0]] - origin, p2 = positions[q[2]] - origin;
    sums.addTriangle(p0, positions[q[1]] - origin, p2);
    sums.addTriangle(p0, p2, positions[q[3]] - origin);
  }
  const double volume = sums.volume / 6;
  const Vec3d first = sums.first / 24;
  const Vec3d squares = sums.squares / 60;
  const Vec3d products = sums.products / 120;

  // Second moments S = int r r^T about `origin`, then about the center of mass:
  // C = S - V c c^T, and the inertia I = trace(C) Id - C.
  Mat3d S;
  S << squares.x(), products.x(), products.z(),  //
      products.x(), squares.y(), products.y(),   //
      products.z(), products.y(), squares.z();
  const Vec3d c = volume != 0 ? Vec3d(first / volume) : Vec3d::Zero();
  const Mat3d C = S - volume * c * c.transpose();
  result.volume = volume;
  result.center = origin + c;
  result.inertia = C.trace() * Mat3d::Identity() - C;
  return result;
}

std::optional<UnmatchedEdge> findUnmatchedEdge(std::span<const Vec3d> positions,
                                               std::span<const Triangle> triangles,
                                               std::span<const Quad> quads) {
  // Points at the same position are one: each point's representative is the first of them.
  std::vector<Index> order(positions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<Index>(i);
  auto lexicographic = [&](Index a, Index b) {
    const Vec3d &p = positions[a], &q = positions[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  };
  std::sort(order.begin(), order.end(), lexicographic);
  std::vector<Index> same(positions.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    same[order[k]] =
        k > 0 && positions[order[k]] == positions[order[k - 1]] ? same[order[k - 1]] : order[k];

  // Each face edge as its unordered pair of representatives and a direction (+1 from the
  // smaller one), with the face's own indices for the report.
  struct DirectedEdge {
    Index low, high;
    int direction;
    bool inQuad;
    std::size_t face;
    Index from, to;
    auto key() const { return std::tie(low, high, inQuad, face); }
  };
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * triangles.size() + 4 * quads.size());
  auto add = [&](Index from, Index to, bool inQuad, std::size_t face) {
    const Index a = same[from], b = same[to];
    if (a == b) return;
    edges.push_back({std::min(a, b), std::max(a, b), a < b ? 1 : -1, inQuad, face, from, to});
  };
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) add(triangles[f][k], triangles[f][(k + 1) % 3], false, f);
  for (std::size_t f = 0; f < quads.size(); ++f)
    for (int k = 0; k < 4; ++k) add(quads[f][k], quads[f][(k + 1) % 4], true, f);
  std::sort(edges.begin(), edges.end(),
            [](const DirectedEdge& a, const DirectedEdge& b) { return a.key() < b.key(); });

  // A closed, consistently oriented surface runs each edge as often one way as the other.
  for (std::size_t begin = 0; begin < edges.size();) {
    std::size_t end = begin;
    int balance = 0;
    for (; end < edges.size() && edges[end].low == edges[begin].low &&
           edges[end].high == edges[begin].high;
         ++end)
      balance += edges[end].direction;
    if (balance != 0) {
      const int excess = balance > 0 ? 1 : -1;
      for (std::size_t i = begin; i < end; ++i)
        if (edges[i].direction == excess)
          return UnmatchedEdge{edges[i].from, edges[i].to, edges[i].face, edges[i].inQuad};
    }
    begin = end;
  }
  return std::nullopt;
}

}  // namespace stroma
