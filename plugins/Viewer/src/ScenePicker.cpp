// SPDX-License-Identifier: MIT
#include "ScenePicker.h"

#include <cmath>
#include <limits>

#include "collision/CollisionModel.h"
#include "core/Node.h"
#include "topology/Topology.h"

namespace stroma::viewer {

namespace {

using Triangles = std::vector<std::array<std::size_t, 3>>;

void addQuads(const std::vector<Quad>& quads, Triangles& out) {
  for (const Quad& q : quads) {
    out.push_back({q[0], q[1], q[2]});
    out.push_back({q[0], q[2], q[3]});
  }
}

Triangles topologyTriangles(const Topology& topology) {
  Triangles out;
  if (!topology.tetrahedra().empty()) {
    for (const Triangle& t : topology.boundaryTriangles()) out.push_back({t[0], t[1], t[2]});
  } else if (!topology.hexahedra().empty()) {
    addQuads(topology.boundaryQuads(), out);
  } else {
    for (const Triangle& t : topology.triangles()) out.push_back({t[0], t[1], t[2]});
    addQuads(topology.quads(), out);
  }
  return out;
}

Triangles collisionTriangles(const Node& node, const Vec3State& state) {
  Triangles out;
  for (const CollisionModel* model : node.getAll<CollisionModel>()) {
    const CollisionGeometry& g = model->geometry();
    if (model->state() != &state || g.kind != PrimitiveKind::triangle) continue;
    for (const auto& t : g.triangles) out.push_back({t[0], t[1], t[2]});
    if (!out.empty()) break;
  }
  return out;
}

// A topology of another state's points (a mesh loaded beside a mapped state) is not this
// state's surface.
bool indicesFit(const Triangles& triangles, std::size_t points) {
  for (const auto& t : triangles)
    if (t[0] >= points || t[1] >= points || t[2] >= points) return false;
  return true;
}

void collect(Node& node, std::vector<PickSurface>& out) {
  for (Vec3State* state : node.getAll<Vec3State>()) {
    PickSurface surface{state, {}};
    if (const Topology* topology = node.get<Topology>()) surface.triangles = topologyTriangles(*topology);
    if (surface.triangles.empty()) surface.triangles = collisionTriangles(node, *state);
    if (!indicesFit(surface.triangles, state->size())) surface.triangles.clear();
    out.push_back(std::move(surface));
  }
  for (const auto& child : node.children())
    if (child->d_activated.value()) collect(*child, out);
}

}  // namespace

std::vector<PickSurface> collectPickSurfaces(Node& root) {
  std::vector<PickSurface> out;
  collect(root, out);
  return out;
}

std::optional<double> intersectTriangle(const Vec3d& origin, const Vec3d& direction,
                                        const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  // Moller and Trumbore (1997): solve origin + s d = a + u (b - a) + v (c - a) by Cramer's rule.
  const Vec3d e1 = b - a, e2 = c - a;
  const Vec3d p = direction.cross(e2);
  const double det = e1.dot(p);
  const double scale = e1.norm() * e2.norm();
  if (std::abs(det) <= 1e-12 * scale) return std::nullopt;  // parallel or degenerate
  const Vec3d t = origin - a;
  const double u = t.dot(p) / det;
  if (u < 0 || u > 1) return std::nullopt;
  const Vec3d q = t.cross(e1);
  const double v = direction.dot(q) / det;
  if (v < 0 || u + v > 1) return std::nullopt;
  const double s = e2.dot(q) / det;
  if (s <= 0) return std::nullopt;
  return s;
}

std::optional<PickedPoint> pickAlongRay(const std::vector<PickSurface>& surfaces,
                                        const Vec3d& origin, const Vec3d& direction,
                                        double pointTolerance) {
  std::optional<PickedPoint> best;
  auto better = [&](double s) { return !best || s < best->rayDistance; };
  for (const PickSurface& surface : surfaces) {
    const auto& x = surface.state->readCoord(VecId::position());
    for (const auto& t : surface.triangles) {
      const auto s = intersectTriangle(origin, direction, x[t[0]], x[t[1]], x[t[2]]);
      if (!s || !better(*s)) continue;
      const Vec3d hit = origin + *s * direction;
      std::size_t nearest = t[0];
      for (std::size_t k : {t[1], t[2]})
        if ((x[k] - hit).squaredNorm() < (x[nearest] - hit).squaredNorm()) nearest = k;
      best = PickedPoint{surface.state, nearest, hit, *s};
    }
    if (!surface.triangles.empty()) continue;
    // Points alone: the nearest to the ray inside the cone, by distance to the ray relative
    // to the cone's width there.
    double bestRatio = std::numeric_limits<double>::infinity();
    std::optional<PickedPoint> nearestPoint;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double s = (x[i] - origin).dot(direction);
      if (s <= 0) continue;
      const double offAxis = (x[i] - origin - s * direction).norm();
      const double ratio = offAxis / (pointTolerance * s);
      if (ratio <= 1 && ratio < bestRatio) {
        bestRatio = ratio;
        nearestPoint = PickedPoint{surface.state, i, x[i], s};
      }
    }
    if (nearestPoint && better(nearestPoint->rayDistance)) best = nearestPoint;
  }
  return best;
}

}  // namespace stroma::viewer
