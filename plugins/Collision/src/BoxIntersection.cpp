// SPDX-License-Identifier: MIT
#include "BoxIntersection.h"

#include "Collision/kernels/ConvexContact.h"
#include "Collision/kernels/Proximity.h"

namespace stroma::collision {

namespace {

// Parameters within this of an end of a segment or triangle are on its boundary (SOFA's value,
// as in PrimitiveIntersection).
constexpr double kInterior = 1e-6;

// Whether triangle t keeps a contact point with these barycentric coordinates: inside always; on
// an edge or a vertex when no line (point) model of its surface tests the edges (vertices) and
// it owns that feature.
bool triangleKeeps(const CollisionGeometry& g, std::uint32_t t, const Vec3d& barycentric) {
  int zeros = 0, zero = -1, one = -1;
  for (int k = 0; k < 3; ++k) {
    if (barycentric[k] <= kInterior)
      ++zeros, zero = k;
    else
      one = k;
  }
  if (zeros == 0) return true;
  const bool edge = zeros == 1;
  if (edge ? g.edgesElsewhere : g.verticesElsewhere) return false;
  const int bit = edge ? 3 + (zero + 1) % 3 : one;  // edge (zero + 1, zero + 2), or a vertex
  return g.featureOwnership.empty() || (g.featureOwnership[t] >> bit & 1u);
}

Contact makeContact(std::uint32_t i, std::uint32_t j, const Vec3d& normal,
                    const ConvexContactPoint& p, const Vec3d& otherWeights) {
  Contact c;
  c.primitive[0] = i;
  c.primitive[1] = j;
  c.point[0] = p.onFirst;
  c.point[1] = p.onSecond;
  c.weights[0] = Vec3d(1, 0, 0);
  c.weights[1] = otherWeights;
  c.normal = normal;
  c.distance = p.distance;
  return c;
}

}  // namespace

int intersectBox(const CollisionGeometry& box, std::uint32_t i, const CollisionGeometry& other,
                 std::uint32_t j, bool otherBothSide, double limit,
                 std::array<Contact, kMaxBoxContacts>& out) {
  const ConvexPrimitive first = ConvexPrimitive::orientedBox(box.boxes[i]);
  ConvexPrimitive second;
  double radius = 0;
  switch (other.kind) {
    case PrimitiveKind::box:
      second = ConvexPrimitive::orientedBox(other.boxes[j]);
      break;
    case PrimitiveKind::sphere:
      radius = other.radius(j);
      second = ConvexPrimitive::point(other.points[j]);
      break;
    case PrimitiveKind::point:
      second = ConvexPrimitive::point(other.points[j]);
      break;
    case PrimitiveKind::line:
      second = ConvexPrimitive::segment(other.points[other.edges[j][0]],
                                        other.points[other.edges[j][1]]);
      break;
    case PrimitiveKind::triangle: {
      const auto& t = other.triangles[j];
      second = ConvexPrimitive::triangle(other.points[t[0]], other.points[t[1]], other.points[t[2]],
                                         !otherBothSide);
      break;
    }
  }
  ConvexContacts contacts;
  if (!computeConvexContacts(first, second, limit + radius, contacts)) return 0;

  int count = 0;
  for (int k = 0; k < contacts.count && count < kMaxBoxContacts; ++k) {
    ConvexContactPoint p = contacts.points[k];
    Vec3d weights(1, 0, 0);
    switch (other.kind) {
      case PrimitiveKind::sphere:
        // The point on the sphere's surface, the gap between the surfaces.
        p.onSecond -= radius * contacts.normal;
        p.distance -= radius;
        break;
      case PrimitiveKind::line: {
        const Vec3d &a = second.vertices[0], &b = second.vertices[1];
        const double t = closestPointOnSegment(p.onSecond, a, b).t;
        if (!(t > kInterior && t < 1 - kInterior)) continue;  // the point model's
        weights = Vec3d(1 - t, t, 0);
        break;
      }
      case PrimitiveKind::triangle: {
        const auto& v = second.vertices;
        weights = closestPointOnTriangle(p.onSecond, v[0], v[1], v[2]).barycentric;
        if (!triangleKeeps(other, j, weights)) continue;
        break;
      }
      case PrimitiveKind::box:
      case PrimitiveKind::point:
        break;
    }
    out[count++] = makeContact(i, j, contacts.normal, p, weights);
  }
  return count;
}

}  // namespace stroma::collision
