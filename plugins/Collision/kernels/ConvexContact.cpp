// SPDX-License-Identifier: MIT
#include "Collision/kernels/ConvexContact.h"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "Collision/kernels/Proximity.h"

namespace stroma::collision {

ConvexPrimitive ConvexPrimitive::point(const Vec3d& p) {
  ConvexPrimitive c;
  c.kind = Kind::point;
  c.vertices = {p, p, p};
  return c;
}

ConvexPrimitive ConvexPrimitive::segment(const Vec3d& a, const Vec3d& b) {
  ConvexPrimitive c;
  c.kind = Kind::segment;
  c.vertices = {a, b, b};
  return c;
}

ConvexPrimitive ConvexPrimitive::triangle(const Vec3d& a, const Vec3d& b, const Vec3d& c,
                                          bool oneSided) {
  ConvexPrimitive t;
  t.kind = Kind::triangle;
  t.vertices = {a, b, c};
  t.oneSided = oneSided;
  return t;
}

ConvexPrimitive ConvexPrimitive::orientedBox(const OrientedBox& box) {
  ConvexPrimitive c;
  c.kind = Kind::box;
  c.box = box;
  return c;
}

namespace {

constexpr int kMaxVertices = 8;
constexpr int kMaxFaces = 6;
constexpr int kMaxEdgeDirections = 3;
constexpr int kClipCapacity = 32;

// A primitive as a polytope in double: its vertices, faces (outward normals, vertices in cyclic
// order) and edge directions.
struct Polytope {
  ConvexPrimitive::Kind kind = ConvexPrimitive::Kind::point;
  int vertexCount = 0;
  std::array<Vec3d, kMaxVertices> vertices;
  int faceCount = 0;
  std::array<std::array<int, 4>, kMaxFaces> faces;
  std::array<int, kMaxFaces> faceSize{};
  std::array<Vec3d, kMaxFaces> faceNormals;
  int edgeCount = 0;
  std::array<Vec3d, kMaxEdgeDirections> edgeDirections;
  // Triangles: the edge of each direction (vertex k to k + 1).
  Vec3d centre = Vec3d::Zero();
  double size = 0;  // the longest distance between two of its vertices (a bound)
  bool oneSided = false;
  Vec3d frontNormal = Vec3d::UnitZ();  // one-sided triangles
};

// Box vertex k: centre + sum_i s_i h_i a_i with s_i = +1 when bit i of k is set.
Vec3d boxVertex(const OrientedBox& b, int k) {
  Vec3d local;
  for (int i = 0; i < 3; ++i) local[i] = (k >> i & 1) ? b.halfExtents[i] : -b.halfExtents[i];
  return b.center + b.rotation * local;
}

Polytope makePolytope(const ConvexPrimitive& p) {
  Polytope q;
  q.kind = p.kind;
  q.oneSided = p.oneSided;
  using K = ConvexPrimitive::Kind;
  switch (p.kind) {
    case K::point:
      q.vertexCount = 1;
      q.vertices[0] = p.vertices[0];
      break;
    case K::segment:
      q.vertexCount = 2;
      q.vertices[0] = p.vertices[0];
      q.vertices[1] = p.vertices[1];
      q.edgeCount = 1;
      q.edgeDirections[0] = p.vertices[1] - p.vertices[0];
      break;
    case K::triangle: {
      q.vertexCount = 3;
      for (int k = 0; k < 3; ++k) q.vertices[k] = p.vertices[k];
      const Vec3d n = (p.vertices[1] - p.vertices[0]).cross(p.vertices[2] - p.vertices[0]);
      const double length = n.norm();
      q.frontNormal = length > 0 ? Vec3d(n / length) : Vec3d::UnitZ();
      // Both sides as faces (the front one only when one-sided).
      q.faceCount = p.oneSided ? 1 : 2;
      q.faces[0] = {0, 1, 2, 0};
      q.faceSize[0] = 3;
      q.faceNormals[0] = q.frontNormal;
      q.faces[1] = {0, 2, 1, 0};
      q.faceSize[1] = 3;
      q.faceNormals[1] = -q.frontNormal;
      q.edgeCount = 3;
      for (int k = 0; k < 3; ++k) q.edgeDirections[k] = p.vertices[(k + 1) % 3] - p.vertices[k];
      if (length == 0) q.faceCount = 0;  // a flat triangle has no face to rest on
      break;
    }
    case K::box: {
      const OrientedBox& b = p.box;
      q.vertexCount = 8;
      for (int k = 0; k < 8; ++k) q.vertices[k] = boxVertex(b, k);
      q.faceCount = 6;
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, l = (i + 2) % 3;
        for (int sign = 0; sign < 2; ++sign) {
          const int f = 2 * i + sign;
          const int fixed = sign << i;
          // (j, l) bits (0,0), (1,0), (1,1), (0,1): a cycle, counter-clockwise around +a_i
          // for sign 1 (a_j x a_l = a_i), clockwise for sign 0.
          std::array<int, 4> face = {fixed, fixed | 1 << j, fixed | 1 << j | 1 << l,
                                     fixed | 1 << l};
          if (sign == 0) std::swap(face[1], face[3]);
          q.faces[f] = face;
          q.faceSize[f] = 4;
          q.faceNormals[f] = sign ? Vec3d(b.rotation.col(i)) : Vec3d(-b.rotation.col(i));
        }
        q.edgeDirections[i] = b.rotation.col(i);
      }
      q.edgeCount = 3;
      break;
    }
  }
  Vec3d sum = Vec3d::Zero();
  for (int k = 0; k < q.vertexCount; ++k) sum += q.vertices[k];
  q.centre = sum / q.vertexCount;
  for (int a = 0; a < q.vertexCount; ++a)
    for (int b = a + 1; b < q.vertexCount; ++b)
      q.size = std::max(q.size, (q.vertices[a] - q.vertices[b]).norm());
  return q;
}

double maxDot(const Polytope& p, const Vec3d& d) {
  double m = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < p.vertexCount; ++k) m = std::max(m, d.dot(p.vertices[k]));
  return m;
}

double minDot(const Polytope& p, const Vec3d& d) {
  double m = std::numeric_limits<double>::infinity();
  for (int k = 0; k < p.vertexCount; ++k) m = std::min(m, d.dot(p.vertices[k]));
  return m;
}

// A convex polygon of up to 4 vertices in cyclic order (1: a point, 2: a segment).
struct Feature {
  int count = 0;
  std::array<Vec3d, 4> vertices;
};

// The vertices of p whose height along d is within tolerance of the highest: a face, an edge or a
// vertex of p. A box's is built axis by axis (an axis whose two vertices differ by at most the
// tolerance along d is spanned), so that it is always a whole face, edge or vertex.
Feature supportFeature(const Polytope& p, const ConvexPrimitive& primitive, const Vec3d& d,
                       double tolerance) {
  Feature f;
  if (p.kind == ConvexPrimitive::Kind::box) {
    const OrientedBox& b = primitive.box;
    int fixedBits = 0, spanned[2] = {-1, -1}, spans = 0;
    for (int i = 0; i < 3; ++i) {
      const double along = d.dot(b.rotation.col(i));
      if (2 * b.halfExtents[i] * std::abs(along) <= tolerance && spans < 2)
        spanned[spans++] = i;
      else if (along > 0)
        fixedBits |= 1 << i;
    }
    if (spans == 0) {
      f.count = 1;
      f.vertices[0] = p.vertices[fixedBits];
    } else if (spans == 1) {
      f.count = 2;
      f.vertices[0] = p.vertices[fixedBits];
      f.vertices[1] = p.vertices[fixedBits | 1 << spanned[0]];
    } else {
      const int u = 1 << spanned[0], v = 1 << spanned[1];
      f.count = 4;
      f.vertices = {p.vertices[fixedBits], p.vertices[fixedBits | u], p.vertices[fixedBits | u | v],
                    p.vertices[fixedBits | v]};
    }
    return f;
  }
  const double top = maxDot(p, d);
  for (int k = 0; k < p.vertexCount; ++k)
    if (d.dot(p.vertices[k]) >= top - tolerance) f.vertices[f.count++] = p.vertices[k];
  return f;
}

struct PointPair {
  Vec3d onFirst, onSecond;
  double distance = std::numeric_limits<double>::infinity();
};

// The closest point of a feature to x.
void closestOnFeature(const Vec3d& x, const Feature& f, Vec3d& closest, double& distance) {
  switch (f.count) {
    case 1:
      closest = f.vertices[0];
      distance = (x - closest).norm();
      return;
    case 2: {
      const PointSegmentResult r = closestPointOnSegment(x, f.vertices[0], f.vertices[1]);
      closest = r.closest;
      distance = r.distance;
      return;
    }
    default: {
      PointTriangleResult best =
          closestPointOnTriangle(x, f.vertices[0], f.vertices[1], f.vertices[2]);
      if (f.count == 4) {
        const PointTriangleResult other =
            closestPointOnTriangle(x, f.vertices[0], f.vertices[2], f.vertices[3]);
        if (other.distance < best.distance) best = other;
      }
      closest = best.closest;
      distance = best.distance;
    }
  }
}

// The exact closest points of two convex polygons that do not intersect: the nearest of each
// vertex against the other polygon and each edge against each edge.
PointPair closestPointsOfFeatures(const Feature& a, const Feature& b) {
  PointPair best;
  Vec3d closest;
  double distance = 0;
  for (int k = 0; k < a.count; ++k) {
    closestOnFeature(a.vertices[k], b, closest, distance);
    if (distance < best.distance) best = {a.vertices[k], closest, distance};
  }
  for (int k = 0; k < b.count; ++k) {
    closestOnFeature(b.vertices[k], a, closest, distance);
    if (distance < best.distance) best = {closest, b.vertices[k], distance};
  }
  if (a.count >= 2 && b.count >= 2) {
    const int ea = a.count == 2 ? 1 : a.count, eb = b.count == 2 ? 1 : b.count;
    for (int i = 0; i < ea; ++i)
      for (int j = 0; j < eb; ++j) {
        const SegmentSegmentResult r =
            closestPointsOfSegments(a.vertices[i], a.vertices[(i + 1) % a.count], b.vertices[j],
                                    b.vertices[(j + 1) % b.count]);
        if (r.distance < best.distance) best = {r.closestOnFirst, r.closestOnSecond, r.distance};
      }
  }
  return best;
}

// The closest point of primitive p (as a solid) to x.
Vec3d closestOnPrimitive(const Vec3d& x, const Polytope& q, const ConvexPrimitive& p) {
  using K = ConvexPrimitive::Kind;
  switch (p.kind) {
    case K::point:
      return q.vertices[0];
    case K::segment:
      return closestPointOnSegment(x, q.vertices[0], q.vertices[1]).closest;
    case K::triangle:
      return closestPointOnTriangle(x, q.vertices[0], q.vertices[1], q.vertices[2]).closest;
    case K::box: {
      const OrientedBox& b = p.box;
      const Vec3d local = b.rotation.transpose() * (x - b.center);
      return b.center + b.rotation * local.cwiseMax(-b.halfExtents).cwiseMin(b.halfExtents);
    }
  }
  return x;
}

// The edges of a primitive as vertex index pairs: a box's 12, a triangle's 3, a segment's 1.
int primitiveEdges(const Polytope& q, std::array<std::array<int, 2>, 12>& edges) {
  using K = ConvexPrimitive::Kind;
  int n = 0;
  switch (q.kind) {
    case K::point:
      break;
    case K::segment:
      edges[n++] = {0, 1};
      break;
    case K::triangle:
      for (int k = 0; k < 3; ++k) edges[n++] = {k, (k + 1) % 3};
      break;
    case K::box:
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 8; ++k)
          if (!(k >> i & 1)) edges[n++] = {k, k | 1 << i};
      break;
  }
  return n;
}

// The exact closest points of two primitives that do not intersect, from all their features:
// each vertex of one against the other (a solid) and each edge against each edge (the closest
// points of two convex polytopes are at a vertex of one or on an edge of each). The slow path,
// for when GJK's direction picked the wrong features.
PointPair closestPointsOfPrimitives(const Polytope& a, const ConvexPrimitive& pa, const Polytope& b,
                                    const ConvexPrimitive& pb) {
  PointPair best;
  for (int k = 0; k < a.vertexCount; ++k) {
    const Vec3d q = closestOnPrimitive(a.vertices[k], b, pb);
    const double d = (q - a.vertices[k]).norm();
    if (d < best.distance) best = {a.vertices[k], q, d};
  }
  for (int k = 0; k < b.vertexCount; ++k) {
    const Vec3d q = closestOnPrimitive(b.vertices[k], a, pa);
    const double d = (q - b.vertices[k]).norm();
    if (d < best.distance) best = {q, b.vertices[k], d};
  }
  std::array<std::array<int, 2>, 12> ea, eb;
  const int na = primitiveEdges(a, ea), nb = primitiveEdges(b, eb);
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) {
      const SegmentSegmentResult r = closestPointsOfSegments(
          a.vertices[ea[i][0]], a.vertices[ea[i][1]], b.vertices[eb[j][0]], b.vertices[eb[j][1]]);
      if (r.distance < best.distance) best = {r.closestOnFirst, r.closestOnSecond, r.distance};
    }
  return best;
}

// --- Bullet ------------------------------------------------------------------------------------

btVector3 toBullet(const Vec3d& v) {
  return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z()));
}
Vec3d fromBullet(const btVector3& v) { return Vec3d(v.x(), v.y(), v.z()); }

// A Bullet shape for a primitive, in coordinates (x - origin) / scale: Bullet's tolerances are
// absolute (GJK_MIN_DISTANCE = 1e-4), so the pair is brought to unit size around the first.
struct BulletShape {
  btBoxShape box{btVector3(1, 1, 1)};
  btSphereShape sphere{0};
  btTriangleShape triangle;
  btTransform transform = btTransform::getIdentity();
  const btConvexShape* shape = nullptr;

  BulletShape(const ConvexPrimitive& p, const Vec3d& origin, double scale) {
    using K = ConvexPrimitive::Kind;
    auto local = [&](const Vec3d& x) { return toBullet((x - origin) / scale); };
    switch (p.kind) {
      case K::point:  // a sphere of radius 0: its support is its centre
        sphere.setMargin(0);
        transform.setOrigin(local(p.vertices[0]));
        shape = &sphere;
        break;
      case K::segment:  // a triangle with two equal vertices
      case K::triangle:
        triangle =
            btTriangleShape(local(p.vertices[0]), local(p.vertices[1]), local(p.vertices[2]));
        triangle.setMargin(0);
        shape = &triangle;
        break;
      case K::box: {
        // setMargin keeps the half extents with margin: set the margin first, then the size.
        box.setMargin(0);
        box.setImplicitShapeDimensions(toBullet(p.box.halfExtents / scale));
        const Mat3d& R = p.box.rotation;
        transform.setBasis(btMatrix3x3(btScalar(R(0, 0)), btScalar(R(0, 1)), btScalar(R(0, 2)),
                                       btScalar(R(1, 0)), btScalar(R(1, 1)), btScalar(R(1, 2)),
                                       btScalar(R(2, 0)), btScalar(R(2, 1)), btScalar(R(2, 2))));
        transform.setOrigin(local(p.box.center));
        shape = &box;
        break;
      }
    }
  }
};

// Where Bullet works: around the smaller primitive, in units of its size, so that GJK's
// absolute tolerances are relative to the finer of the two (a box on a large floor triangle).
void bulletFrame(const Polytope& a, const Polytope& b, Vec3d& origin, double& unit) {
  const bool aFirst = a.size > 0 && (b.size == 0 || a.size <= b.size);
  const Polytope& small = aFirst ? a : b;
  origin = small.centre;
  unit = small.size > 0
             ? small.size
             : std::max((b.centre - a.centre).norm(), std::numeric_limits<double>::min());
}

GjkEpaResult gjkEpa(const ConvexPrimitive& first, const ConvexPrimitive& second,
                    const Vec3d& origin, double scale) {
  GjkEpaResult out;
  const BulletShape a(first, origin, scale), b(second, origin, scale);
  btGjkEpaSolver2::sResults r;
  const btVector3 guess = b.transform.getOrigin() - a.transform.getOrigin();
  if (btGjkEpaSolver2::Distance(a.shape, a.transform, b.shape, b.transform, guess, r)) {
    out.status = GjkEpaResult::Status::separated;
    out.onFirst = origin + scale * fromBullet(r.witnesses[0]);
    out.onSecond = origin + scale * fromBullet(r.witnesses[1]);
    const Vec3d d = out.onSecond - out.onFirst;
    out.distance = d.norm();
    if (out.distance > 0) out.normal = d / out.distance;
    return out;
  }
  if (r.status != btGjkEpaSolver2::sResults::Penetrating) return out;
  if (btGjkEpaSolver2::Penetration(a.shape, a.transform, b.shape, b.transform, guess, r,
                                   /*usemargins=*/false)) {
    // Bullet's normal is in the first shape's frame and points from the second to the first.
    out.status = GjkEpaResult::Status::penetrating;
    out.onFirst = origin + scale * fromBullet(r.witnesses[0]);
    out.onSecond = origin + scale * fromBullet(r.witnesses[1]);
    const Vec3d n = -fromBullet(a.transform.getBasis() * r.normal);
    const double length = n.norm();
    if (length > 0) out.normal = n / length;
    out.distance = scale * double(r.distance);
  }
  return out;
}

// --- Contacts ----------------------------------------------------------------------------------

// A candidate penetration axis: from the first primitive to the second, with the separation of
// the two along it, s = min over the second - max over the first (negative: overlap).
struct Axis {
  Vec3d direction;
  double separation = -std::numeric_limits<double>::infinity();
  enum class Kind { faceOfFirst, faceOfSecond, edges } kind = Kind::edges;
  int first = 0, second = 0;  // the face, or the edge directions
};

// Whether a contact normal n (first to second) is allowed by one-sided triangles: the other
// primitive must be pushed to the triangle's front.
bool allowedByOneSided(const Polytope& a, const Polytope& b, const Vec3d& n) {
  if (a.oneSided && n.dot(a.frontNormal) < 0) return false;
  if (b.oneSided && n.dot(b.frontNormal) > 0) return false;
  return true;
}

// Every candidate axis of the separating-axis test calls visit(axis): each face normal of the
// first (outward, so from the first to the second), each face normal of the second (reversed),
// and both orientations of the cross product of an edge of each.
template <class Visit>
void forEachAxis(const Polytope& a, const Polytope& b, Visit&& visit) {
  auto consider = [&](const Vec3d& direction, Axis::Kind kind, int i, int j) {
    if (!allowedByOneSided(a, b, direction)) return;
    Axis axis;
    axis.direction = direction;
    axis.separation = minDot(b, direction) - maxDot(a, direction);
    axis.kind = kind;
    axis.first = i;
    axis.second = j;
    visit(axis);
  };
  for (int f = 0; f < a.faceCount; ++f) consider(a.faceNormals[f], Axis::Kind::faceOfFirst, f, 0);
  for (int f = 0; f < b.faceCount; ++f) consider(-b.faceNormals[f], Axis::Kind::faceOfSecond, f, 0);
  for (int i = 0; i < a.edgeCount; ++i)
    for (int j = 0; j < b.edgeCount; ++j) {
      const Vec3d &u = a.edgeDirections[i], &v = b.edgeDirections[j];
      const Vec3d c = u.cross(v);
      const double length = c.norm();
      if (!(length > 1e-9 * u.norm() * v.norm())) continue;  // parallel edges
      consider(c / length, Axis::Kind::edges, i, j);
      consider(-c / length, Axis::Kind::edges, i, j);
    }
}

// The face of p whose outward normal is most opposed to d (the face a body shows to a direction).
int incidentFace(const Polytope& p, const Vec3d& d) {
  int best = -1;
  double lowest = std::numeric_limits<double>::infinity();
  for (int f = 0; f < p.faceCount; ++f) {
    const double along = p.faceNormals[f].dot(d);
    if (along < lowest) lowest = along, best = f;
  }
  return best;
}

struct ClipBuffer {
  int count = 0;
  std::array<Vec3d, kClipCapacity> points;
  void push(const Vec3d& x) {
    if (count < kClipCapacity) points[count++] = x;
  }
};

// Appends to `out` the contacts of a reference face (of `reference`, outward normal nR towards
// the other primitive) with the other's incident feature: the incident vertices clipped to the
// face's side planes (Sutherland-Hodgman), each at gap nR.(x - face) when below limit.
void faceContacts(const Polytope& reference, int face, const Polytope& incident,
                  bool referenceIsFirst, double limit, ConvexContacts& out) {
  const Vec3d nR = reference.faceNormals[face];
  const int nr = reference.faceSize[face];
  std::array<Vec3d, 4> R;
  Vec3d centroid = Vec3d::Zero();
  for (int k = 0; k < nr; ++k) {
    R[k] = reference.vertices[reference.faces[face][k]];
    centroid += R[k];
  }
  centroid /= nr;
  const double scale = std::max(reference.size, incident.size);
  const double eps = 1e-12 * scale;

  // The incident polygon: the face turned most against nR, or the whole primitive.
  ClipBuffer polygon;
  const int f = incidentFace(incident, nR);
  if (f >= 0)
    for (int k = 0; k < incident.faceSize[f]; ++k)
      polygon.push(incident.vertices[incident.faces[f][k]]);
  else
    for (int k = 0; k < incident.vertexCount; ++k) polygon.push(incident.vertices[k]);

  // Clip against each side plane m.(x - r_k) <= 0, m the outward normal of edge k in the face.
  for (int k = 0; k < nr && polygon.count > 0; ++k) {
    const Vec3d& r = R[k];
    Vec3d m = (R[(k + 1) % nr] - r).cross(nR);
    if (m.dot(centroid - r) > 0) m = -m;
    const double mn = m.norm();
    if (!(mn > 0)) continue;
    m /= mn;
    ClipBuffer next;
    if (polygon.count == 1) {
      if (m.dot(polygon.points[0] - r) <= eps) next.push(polygon.points[0]);
    } else {
      const int n = polygon.count == 2 ? 1 : polygon.count;  // a segment has one edge
      for (int e = 0; e < n; ++e) {
        const Vec3d& p = polygon.points[e];
        const Vec3d& q = polygon.points[(e + 1) % polygon.count];
        const double dp = m.dot(p - r), dq = m.dot(q - r);
        const bool pIn = dp <= eps, qIn = dq <= eps;
        if (pIn) next.push(p);
        if (pIn != qIn) next.push(p + (dp / (dp - dq)) * (q - p));
        if (polygon.count == 2 && qIn) next.push(q);
      }
    }
    polygon = next;
  }

  const Vec3d normal = referenceIsFirst ? nR : Vec3d(-nR);
  const double planeOffset = nR.dot(R[0]);
  for (int k = 0; k < polygon.count && out.count < ConvexContacts::kMaxPoints; ++k) {
    const Vec3d& x = polygon.points[k];
    bool duplicate = false;
    for (int c = 0; c < out.count && !duplicate; ++c)
      duplicate =
          ((referenceIsFirst ? out.points[c].onSecond : out.points[c].onFirst) - x).squaredNorm() <=
          eps * eps * 1e4;
    if (duplicate) continue;
    const double gap = nR.dot(x) - planeOffset;
    if (!(gap < limit)) continue;
    const Vec3d onReference = x - gap * nR;
    ConvexContactPoint& c = out.points[out.count++];
    c.onFirst = referenceIsFirst ? onReference : x;
    c.onSecond = referenceIsFirst ? x : onReference;
    c.distance = gap;
  }
  out.normal = normal;
  out.faceContact = true;
}

void singleContact(const Vec3d& onFirst, const Vec3d& onSecond, const Vec3d& normal,
                   double distance, ConvexContacts& out) {
  // onSecond - onFirst = distance * normal exactly (the two points moved along the normal by
  // rounding at most), so that equal and opposite forces on them have no net moment.
  const Vec3d middle = 0.5 * (onFirst + onSecond);
  out.count = 1;
  out.normal = normal;
  out.points[0] = {middle - 0.5 * distance * normal, middle + 0.5 * distance * normal, distance};
  out.faceContact = false;
}

// The face of p (outward normal f) whose normal is d to rounding, or -1.
int faceWithNormal(const Polytope& p, const Vec3d& d) {
  for (int f = 0; f < p.faceCount; ++f)
    if (p.faceNormals[f].dot(d) >= 1 - 1e-9) return f;
  return -1;
}

// The edge of p parallel to edge direction i that is farthest along d (the support edge).
std::array<Vec3d, 2> supportEdge(const Polytope& p, const ConvexPrimitive& primitive, int i,
                                 const Vec3d& d) {
  if (p.kind == ConvexPrimitive::Kind::box) {
    int bits = 0;
    for (int k = 0; k < 3; ++k)
      if (k != i && d.dot(primitive.box.rotation.col(k)) > 0) bits |= 1 << k;
    return {p.vertices[bits], p.vertices[bits | 1 << i]};
  }
  if (p.kind == ConvexPrimitive::Kind::segment) return {p.vertices[0], p.vertices[1]};
  return {p.vertices[i], p.vertices[(i + 1) % 3]};  // a triangle's edge i
}

// The contacts along a penetration axis (or a separating one when touching).
void axisContacts(const Polytope& a, const ConvexPrimitive& pa, const Polytope& b,
                  const ConvexPrimitive& pb, const Axis& axis, double limit, ConvexContacts& out) {
  out.distance = axis.separation;
  switch (axis.kind) {
    case Axis::Kind::faceOfFirst:
      faceContacts(a, axis.first, b, true, limit, out);
      break;
    case Axis::Kind::faceOfSecond:
      faceContacts(b, axis.first, a, false, limit, out);
      break;
    case Axis::Kind::edges: {
      const auto ea = supportEdge(a, pa, axis.first, axis.direction);
      const auto eb = supportEdge(b, pb, axis.second, -axis.direction);
      const SegmentSegmentResult r = closestPointsOfSegments(ea[0], ea[1], eb[0], eb[1]);
      if (axis.separation < limit)
        singleContact(r.closestOnFirst, r.closestOnSecond, axis.direction, axis.separation, out);
      break;
    }
  }
}

}  // namespace

GjkEpaResult computeGjkEpa(const ConvexPrimitive& first, const ConvexPrimitive& second) {
  const Polytope a = makePolytope(first), b = makePolytope(second);
  Vec3d origin;
  double unit = 0;
  bulletFrame(a, b, origin, unit);
  return gjkEpa(first, second, origin, unit);
}

bool computeConvexContacts(const ConvexPrimitive& first, const ConvexPrimitive& second,
                           double limit, ConvexContacts& out) {
  out.count = 0;
  out.faceContact = false;
  out.usedFallback = false;
  const Polytope a = makePolytope(first), b = makePolytope(second);
  // A one-sided triangle has no contact with a primitive whose centre is behind it.
  if (a.oneSided && a.frontNormal.dot(b.centre - a.centre) < 0) return false;
  if (b.oneSided && b.frontNormal.dot(a.centre - b.centre) < 0) return false;

  const double scale =
      std::max({a.size, b.size, (b.centre - a.centre).norm(), std::numeric_limits<double>::min()});
  Vec3d origin;
  double unit = 0;
  bulletFrame(a, b, origin, unit);
  const GjkEpaResult bullet = gjkEpa(first, second, origin, unit);

  // Separated primitives from their exact closest points: the contact polygon when the closest
  // direction is a face normal of either (vertex, edge or face against a face), else those
  // points. False when a one-sided triangle bars that direction.
  auto contactsFromClosest = [&](const PointPair& closest) {
    out.distance = closest.distance;
    if (!(closest.distance < limit)) return true;  // no contact
    const Vec3d n = (closest.onSecond - closest.onFirst) / closest.distance;
    if (!allowedByOneSided(a, b, n)) return false;
    const int fA = faceWithNormal(a, n), fB = faceWithNormal(b, -n);
    if (fA >= 0)
      faceContacts(a, fA, b, true, limit, out);
    else if (fB >= 0)
      faceContacts(b, fB, a, false, limit, out);
    if (out.count == 0) singleContact(closest.onFirst, closest.onSecond, n, closest.distance, out);
    out.distance = closest.distance;
    return true;
  };

  if (bullet.status == GjkEpaResult::Status::separated && bullet.distance > 1e-9 * scale) {
    // Any direction n bounds the distance from below by the separation along it, s(n) = min
    // over the second of n.x - max over the first: none closer than limit when s >= limit.
    auto separation = [&](const Vec3d& n) { return minDot(b, n) - maxDot(a, n); };
    if (separation(bullet.normal) >= limit) return false;
    // The features of each primitive that face the other, generously (the direction is good to
    // about float precision over the distance), then their exact closest points.
    const double tolerance =
        scale * std::min(1.0, 1e-4 + 1e-6 * scale / std::max(bullet.distance, 1e-12 * scale));
    const Feature fa = supportFeature(a, first, bullet.normal, tolerance);
    const Feature fb = supportFeature(b, second, -bullet.normal, tolerance);
    PointPair closest = closestPointsOfFeatures(fa, fb);
    // They are the closest points of the primitives exactly when the separation along their
    // direction equals their distance (s(n) <= distance for every n, with equality only along
    // the closest direction). GJK in float stops early on a few pairs (0.3 % of random box
    // pairs, off by up to 0.16 of their size, some of them interpenetrating): then every pair of
    // features, whose closest points are certified the same way (they are not when the
    // primitives interpenetrate).
    auto certified = [&](const PointPair& p) {
      return p.distance > 1e-12 * scale &&
             separation((p.onSecond - p.onFirst) / p.distance) >= p.distance - 1e-9 * scale;
    };
    if (!certified(closest)) {
      closest = closestPointsOfPrimitives(a, first, b, second);
      out.usedFallback = true;
    }
    if (certified(closest) && contactsFromClosest(closest)) return out.count > 0;
    // Touching (or the closest direction is barred by a one-sided triangle): the axes below.
  }

  // Interpenetrating or touching: the candidate axis of least overlap near EPA's normal (all
  // candidates when EPA failed). An edge axis parallel to a face axis (edges of parallel faces)
  // ties with it up to rounding: a face wins unless the other is better by 1e-9 of the size, and
  // the first primitive's faces win over the second's the same way.
  const bool haveNormal = bullet.status != GjkEpaResult::Status::failed;
  const double cone = std::cos(kEpaCone), tie = 1e-9 * scale;
  auto better = [&](const Axis& x, const Axis& best) {
    const double bias = (x.kind == best.kind || !std::isfinite(best.separation)) ? 0
                        : int(x.kind) > int(best.kind)                           ? tie
                                                                                 : -tie;
    return x.separation > best.separation + bias;
  };
  Axis nearEpa, anyAxis;
  forEachAxis(a, b, [&](const Axis& axis) {
    if (better(axis, anyAxis)) anyAxis = axis;
    if (haveNormal && axis.direction.dot(bullet.normal) >= cone && better(axis, nearEpa))
      nearEpa = axis;
  });
  // The penetration axis is the candidate of least overlap: EPA's when it is that one (to the
  // tie), otherwise (EPA failed or stopped early) the best of all.
  const bool found = std::isfinite(nearEpa.separation) && !better(anyAxis, nearEpa);
  const Axis& axis = found ? nearEpa : anyAxis;
  out.usedFallback = !found;
  if (!std::isfinite(axis.separation)) return false;  // no axis (a flat triangle edge-on)
  if (axis.separation > 1e-12 * scale) {
    // Separated after all (GJK failed): the exact closest points from every pair of features.
    if (axis.separation >= limit) return false;
    out.usedFallback = true;
    const PointPair closest = closestPointsOfPrimitives(a, first, b, second);
    return contactsFromClosest(closest) && out.count > 0;
  }
  if (!(axis.separation < limit)) return false;
  axisContacts(a, first, b, second, axis, limit, out);
  return out.count > 0;
}

}  // namespace stroma::collision
