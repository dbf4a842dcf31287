// SPDX-License-Identifier: MIT
#include "collision/CollisionModel.h"

#include <algorithm>

namespace stroma {

const char* primitiveKindName(PrimitiveKind kind) {
  switch (kind) {
    case PrimitiveKind::point:
      return "point";
    case PrimitiveKind::line:
      return "line";
    case PrimitiveKind::triangle:
      return "triangle";
    case PrimitiveKind::sphere:
      return "sphere";
    case PrimitiveKind::box:
      return "box";
  }
  return "primitive";
}

std::size_t CollisionGeometry::primitiveCount() const {
  switch (kind) {
    case PrimitiveKind::line:
      return edges.size();
    case PrimitiveKind::triangle:
      return triangles.size();
    case PrimitiveKind::point:
    case PrimitiveKind::sphere:
      return points.size();
    case PrimitiveKind::box:
      return boxes.size();
  }
  return 0;
}

void CollisionModel::computeBoxes(std::vector<Aabb>& boxes, double margin) const {
  const CollisionGeometry& g = m_geometry;
  const double extra = margin + d_contactDistance.value();
  boxes.resize(g.primitiveCount());
  switch (g.kind) {
    case PrimitiveKind::point:
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        boxes[i] = {g.points[i], g.points[i]};
        boxes[i].expand(extra);
      }
      break;
    case PrimitiveKind::sphere:
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        boxes[i] = {g.points[i], g.points[i]};
        boxes[i].expand(extra + g.radius(i));
      }
      break;
    case PrimitiveKind::line:
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto& e = g.edges[i];
        boxes[i] = {g.points[e[0]].cwiseMin(g.points[e[1]]),
                    g.points[e[0]].cwiseMax(g.points[e[1]])};
        boxes[i].expand(extra);
      }
      break;
    case PrimitiveKind::triangle:
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto& t = g.triangles[i];
        const Vec3d &a = g.points[t[0]], &b = g.points[t[1]], &c = g.points[t[2]];
        boxes[i] = {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
        boxes[i].expand(extra);
      }
      break;
    case PrimitiveKind::box:
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        // The half widths of an oriented box along the world axes: |R| h.
        const OrientedBox& b = g.boxes[i];
        const Vec3d halfWidths = b.rotation.cwiseAbs() * b.halfExtents;
        boxes[i] = {b.center - halfWidths, b.center + halfWidths};
        boxes[i].expand(extra);
      }
      break;
  }
}

bool CollisionModel::canCollideWith(const CollisionModel& other) const {
  if (!d_active.value() || !other.d_active.value()) return false;
  // Models of one node (the points, lines and triangles of one surface) are one object.
  if (&other == this || other.node() == node())
    return d_selfCollision.value() && other.d_selfCollision.value();
  if (!d_simulated.value() && !other.d_simulated.value()) return false;
  for (int g : d_group.value())
    if (std::find(other.d_group.value().begin(), other.d_group.value().end(), g) !=
        other.d_group.value().end())
      return false;
  return true;
}

}  // namespace stroma
