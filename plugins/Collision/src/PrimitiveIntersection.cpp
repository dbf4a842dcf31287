// SPDX-License-Identifier: MIT
#include "PrimitiveIntersection.h"

#include <algorithm>
#include <array>

#include "BoxIntersection.h"
#include "Collision/kernels/Proximity.h"

namespace stroma::collision {

namespace {

// Parameters within this of an end of a segment or triangle are on its boundary (SOFA's value).
constexpr double kInterior = 1e-6;

bool interior(double t) { return t > kInterior && t < 1 - kInterior; }

Vec3d unitOr(const Vec3d& v, double length, const Vec3d& fallback) {
  return length > 0 ? Vec3d(v / length) : fallback;
}

// One model of the pair as the tests read it.
struct Side {
  const CollisionGeometry& g;
  double thickness;  // the model's contactDistance
  bool bothSide;
};

// The vertices of primitive `i` (up to 3), for the shared-vertex test.
int primitiveVertices(const CollisionGeometry& g, std::uint32_t i,
                      std::array<std::uint32_t, 3>& v) {
  switch (g.kind) {
    case PrimitiveKind::line:
      v = {g.edges[i][0], g.edges[i][1], 0};
      return 2;
    case PrimitiveKind::triangle:
      v = g.triangles[i];
      return 3;
    case PrimitiveKind::point:
    case PrimitiveKind::sphere:
    case PrimitiveKind::box:
      v = {i, 0, 0};
      return 1;
  }
  return 0;
}

bool shareVertex(const CollisionGeometry& a, std::uint32_t i, const CollisionGeometry& b,
                 std::uint32_t j) {
  std::array<std::uint32_t, 3> va{}, vb{};
  const int na = primitiveVertices(a, i, va), nb = primitiveVertices(b, j, vb);
  for (int x = 0; x < na; ++x)
    for (int y = 0; y < nb; ++y)
      if (va[x] == vb[y]) return true;
  return false;
}

// LocalMinDistance: whether the distance to the other side, in direction u from `at`, has a
// local minimum at `at` over the neighbourhood whose points are listed (entries of `primitive`).
bool isLocalMinimum(const CollisionGeometry& g, std::uint32_t primitive, const Vec3d& at,
                    const Vec3d& u, double cone) {
  if (g.neighborOffsets.empty()) return true;
  const double un = u.norm();
  for (std::uint32_t k = g.neighborOffsets[primitive]; k < g.neighborOffsets[primitive + 1]; ++k) {
    const Vec3d e = g.points[g.neighbors[k]] - at;
    if (u.dot(e) > cone * un * e.norm() + 1e-12 * un * e.norm()) return false;
  }
  return true;
}

Contact makeContact(std::uint32_t i, std::uint32_t j, const Vec3d& p, const Vec3d& q,
                    const Vec3d& wp, const Vec3d& wq, const Vec3d& normal, double distance) {
  Contact c;
  c.primitive[0] = i;
  c.primitive[1] = j;
  c.point[0] = p;
  c.point[1] = q;
  c.weights[0] = wp;
  c.weights[1] = wq;
  c.normal = normal;
  c.distance = distance;
  return c;
}

const Vec3d kFirstVertex(1, 0, 0);

Vec3d vertexWeights(int k) {
  Vec3d w = Vec3d::Zero();
  w[k] = 1;
  return w;
}

// The owner bit (CollisionGeometry::featureOwnership) of the feature of a triangle where a point
// with these barycentric coordinates lies; -1 inside.
int featureBit(const Vec3d& barycentric) {
  int zeros = 0, zero = -1, one = -1;
  for (int k = 0; k < 3; ++k) {
    if (barycentric[k] <= kInterior)
      ++zeros, zero = k;
    else
      one = k;
  }
  if (zeros == 0) return -1;
  if (zeros == 1) return 3 + (zero + 1) % 3;  // the edge (zero + 1, zero + 2)
  return one;                                 // a vertex
}

// Whether triangle t reports a contact at x (barycentric coordinates `barycentric`) with the
// other side in direction u from x: inside it always; on an edge or a vertex only when
// - no line (point) model of its surface tests the edges (vertices), unless featuresElsewhere
//   is false (triangle against triangle, which tests its own features),
// - it owns that feature (one triangle reports a shared edge or vertex), and
// - the feature is the closest part of the surface around it: the other triangle on the edge
//   (every point joined to the vertex) does not turn towards u, u.(y - x) <= 0; otherwise that
//   triangle's inside is closer and reports the contact (a flat floor gives no edge contact).
bool keepsFeature(const CollisionGeometry& g, std::uint32_t t, const Vec3d& barycentric,
                  const Vec3d& x, const Vec3d& u, bool featuresElsewhere = true) {
  const int bit = featureBit(barycentric);
  if (bit < 0) return true;
  if (featuresElsewhere && (bit < 3 ? g.verticesElsewhere : g.edgesElsewhere)) return false;
  if (!(g.featureOwnership[t] >> bit & 1u)) return false;
  const double un = u.norm();
  auto turnsTowards = [&](const Vec3d& y) {
    const Vec3d e = y - x;
    return u.dot(e) > 1e-12 * un * e.norm();
  };
  if (bit >= 3) {
    const std::uint32_t opposite = g.triangleEdgeNeighbors[3 * t + (bit - 3)];
    return opposite == CollisionGeometry::kNoVertex || !turnsTowards(g.points[opposite]);
  }
  const std::uint32_t v = g.triangles[t][bit];
  for (std::uint32_t k = g.neighborOffsets[v]; k < g.neighborOffsets[v + 1]; ++k)
    if (turnsTowards(g.points[g.neighbors[k]])) return false;
  return true;
}

// --- Tests of one pair; `limit` is the largest gap that makes a contact -----------------------

bool pointPoint(const Side& A, std::uint32_t i, const Side& B, std::uint32_t j,
                const IntersectionSettings& s, double limit, Contact& c) {
  const Vec3d &p = A.g.points[i], &q = B.g.points[j];
  const double d = (q - p).norm();
  if (!(d < limit)) return false;
  if (s.localMinimum && (!isLocalMinimum(A.g, i, p, q - p, s.angleCone) ||
                         !isLocalMinimum(B.g, j, q, p - q, s.angleCone)))
    return false;
  c = makeContact(i, j, p, q, kFirstVertex, kFirstVertex, unitOr(q - p, d, Vec3d::UnitZ()), d);
  return true;
}

bool pointLine(const Side& A, std::uint32_t i, const Side& B, std::uint32_t j,
               const IntersectionSettings& s, double limit, Contact& c) {
  const Vec3d& p = A.g.points[i];
  const auto& e = B.g.edges[j];
  const PointSegmentResult r = closestPointOnSegment(p, B.g.points[e[0]], B.g.points[e[1]]);
  if (!interior(r.t) || !(r.distance < limit)) return false;
  if (s.localMinimum && (!isLocalMinimum(A.g, i, p, r.closest - p, s.angleCone) ||
                         !isLocalMinimum(B.g, j, r.closest, p - r.closest, s.angleCone)))
    return false;
  c = makeContact(i, j, p, r.closest, kFirstVertex, Vec3d(1 - r.t, r.t, 0),
                  unitOr(r.closest - p, r.distance, Vec3d::UnitZ()), r.distance);
  return true;
}

bool lineLine(const Side& A, std::uint32_t i, const Side& B, std::uint32_t j,
              const IntersectionSettings& s, double limit, Contact& c) {
  const auto &ea = A.g.edges[i], &eb = B.g.edges[j];
  const Vec3d &p0 = A.g.points[ea[0]], &p1 = A.g.points[ea[1]];
  const Vec3d &q0 = B.g.points[eb[0]], &q1 = B.g.points[eb[1]];
  const SegmentSegmentResult r = closestPointsOfSegments(p0, p1, q0, q1);
  if (!interior(r.s) || !interior(r.t) || !(r.distance < limit)) return false;
  const Vec3d& p = r.closestOnFirst;
  const Vec3d& q = r.closestOnSecond;
  if (s.localMinimum && (!isLocalMinimum(A.g, i, p, q - p, s.angleCone) ||
                         !isLocalMinimum(B.g, j, q, p - q, s.angleCone)))
    return false;
  const Vec3d across = (p1 - p0).cross(q1 - q0);
  c = makeContact(i, j, p, q, Vec3d(1 - r.s, r.s, 0), Vec3d(1 - r.t, r.t, 0),
                  unitOr(q - p, r.distance, unitOr(across, across.norm(), Vec3d::UnitZ())),
                  r.distance);
  return true;
}

bool pointTriangle(const Side& A, std::uint32_t i, const Side& B, std::uint32_t j,
                   const IntersectionSettings& s, double limit, Contact& c) {
  const Vec3d& p = A.g.points[i];
  const auto& t = B.g.triangles[j];
  const PointTriangleResult r =
      closestPointOnTriangle(p, B.g.points[t[0]], B.g.points[t[1]], B.g.points[t[2]]);
  if (!(r.distance < limit) || !keepsFeature(B.g, j, r.barycentric, r.closest, p - r.closest))
    return false;
  const Vec3d& n = B.g.triangleNormals[j];
  if (!B.bothSide && (p - r.closest).dot(n) < 0) return false;  // behind the triangle
  if (s.localMinimum && !isLocalMinimum(A.g, i, p, r.closest - p, s.angleCone)) return false;
  c = makeContact(i, j, p, r.closest, kFirstVertex, r.barycentric,
                  unitOr(r.closest - p, r.distance, -n), r.distance);
  return true;
}

// Sphere i of A against the point, segment, triangle or sphere j of B.
bool spherePrimitive(const Side& A, std::uint32_t i, const Side& B, std::uint32_t j,
                     const IntersectionSettings& s, double limit, Contact& c) {
  const Vec3d& center = A.g.points[i];
  const double radius = A.g.radius(i);
  Vec3d q = center, weights = kFirstVertex, fallback = Vec3d::UnitZ();
  double d = 0, otherRadius = 0;
  switch (B.g.kind) {
    case PrimitiveKind::point:
      q = B.g.points[j];
      d = (q - center).norm();
      break;
    case PrimitiveKind::sphere:
      q = B.g.points[j];
      d = (q - center).norm();
      otherRadius = B.g.radius(j);
      break;
    case PrimitiveKind::line: {
      const auto& e = B.g.edges[j];
      const PointSegmentResult r =
          closestPointOnSegment(center, B.g.points[e[0]], B.g.points[e[1]]);
      if (!interior(r.t)) return false;
      q = r.closest;
      d = r.distance;
      weights = Vec3d(1 - r.t, r.t, 0);
      break;
    }
    case PrimitiveKind::triangle: {
      const auto& t = B.g.triangles[j];
      const PointTriangleResult r =
          closestPointOnTriangle(center, B.g.points[t[0]], B.g.points[t[1]], B.g.points[t[2]]);
      if (!keepsFeature(B.g, j, r.barycentric, r.closest, center - r.closest)) return false;
      const Vec3d& n = B.g.triangleNormals[j];
      if (!B.bothSide && (center - r.closest).dot(n) < 0) return false;
      q = r.closest;
      d = r.distance;
      weights = r.barycentric;
      fallback = -n;
      break;
    }
    case PrimitiveKind::box:  // boxes come first: BoxIntersection
      return false;
  }
  const double gap = d - radius - otherRadius;
  if (!(gap < limit)) return false;
  const Vec3d normal = unitOr(q - center, d, fallback);
  (void)s;
  c = makeContact(i, j, center + radius * normal, q - otherRadius * normal, kFirstVertex, weights,
                  normal, gap);
  return true;
}

// NewProximityIntersection: two triangles through their owned features (see the header).
template <class Emit>
void triangleTriangle(const Side& A, std::uint32_t i, const Side& B, std::uint32_t j, double limit,
                      bool edges, Emit&& emit) {
  const auto &ta = A.g.triangles[i], &tb = B.g.triangles[j];
  const std::uint8_t ownA = A.g.featureOwnership[i], ownB = B.g.featureOwnership[j];
  // A's owned vertices against B.
  for (int k = 0; k < 3; ++k) {
    if (!(ownA >> k & 1u)) continue;
    const Vec3d& p = A.g.points[ta[k]];
    const PointTriangleResult r =
        closestPointOnTriangle(p, B.g.points[tb[0]], B.g.points[tb[1]], B.g.points[tb[2]]);
    if (!(r.distance < limit) ||
        !keepsFeature(B.g, j, r.barycentric, r.closest, p - r.closest, false))
      continue;
    const Vec3d& n = B.g.triangleNormals[j];
    if (!B.bothSide && (p - r.closest).dot(n) < 0) continue;
    emit(makeContact(i, j, p, r.closest, vertexWeights(k), r.barycentric,
                     unitOr(r.closest - p, r.distance, -n), r.distance));
  }
  // B's owned vertices against A, but not on a vertex of A (found above).
  for (int k = 0; k < 3; ++k) {
    if (!(ownB >> k & 1u)) continue;
    const Vec3d& q = B.g.points[tb[k]];
    const PointTriangleResult r =
        closestPointOnTriangle(q, A.g.points[ta[0]], A.g.points[ta[1]], A.g.points[ta[2]]);
    const int bit = featureBit(r.barycentric);
    if (!(r.distance < limit) || (bit >= 0 && bit < 3) ||
        !keepsFeature(A.g, i, r.barycentric, r.closest, q - r.closest, false))
      continue;
    const Vec3d& n = A.g.triangleNormals[i];
    if (!A.bothSide && (q - r.closest).dot(n) < 0) continue;
    emit(makeContact(i, j, r.closest, q, r.barycentric, vertexWeights(k),
                     unitOr(q - r.closest, r.distance, n), r.distance));
  }
  // Owned edges against owned edges, interiors only.
  for (int ka = 0; ka < 3 && edges; ++ka) {
    if (!(ownA >> (3 + ka) & 1u)) continue;
    const Vec3d &p0 = A.g.points[ta[ka]], &p1 = A.g.points[ta[(ka + 1) % 3]];
    for (int kb = 0; kb < 3; ++kb) {
      if (!(ownB >> (3 + kb) & 1u)) continue;
      const Vec3d &q0 = B.g.points[tb[kb]], &q1 = B.g.points[tb[(kb + 1) % 3]];
      const SegmentSegmentResult r = closestPointsOfSegments(p0, p1, q0, q1);
      if (!interior(r.s) || !interior(r.t) || !(r.distance < limit)) continue;
      Vec3d wa = Vec3d::Zero(), wb = Vec3d::Zero();
      wa[ka] = 1 - r.s;
      wa[(ka + 1) % 3] = r.s;
      wb[kb] = 1 - r.t;
      wb[(kb + 1) % 3] = r.t;
      const Vec3d across = (p1 - p0).cross(q1 - q0);
      emit(makeContact(i, j, r.closestOnFirst, r.closestOnSecond, wa, wb,
                       unitOr(r.closestOnSecond - r.closestOnFirst, r.distance,
                              unitOr(across, across.norm(), Vec3d::UnitZ())),
                       r.distance));
    }
  }
}

Contact flipped(const Contact& c) {
  Contact f = c;
  std::swap(f.primitive[0], f.primitive[1]);
  std::swap(f.point[0], f.point[1]);
  std::swap(f.weights[0], f.weights[1]);
  f.normal = -c.normal;
  return f;
}

// Kinds in the order of the tests' first argument: point < line < triangle < sphere, except
// that boxes come first against everything (BoxIntersection handles every other kind), then
// spheres (spherePrimitive handles every other kind but boxes).
int rank(PrimitiveKind k) {
  switch (k) {
    case PrimitiveKind::box:
      return -1;
    case PrimitiveKind::sphere:
      return 0;
    case PrimitiveKind::point:
      return 1;
    case PrimitiveKind::line:
      return 2;
    case PrimitiveKind::triangle:
      return 3;
  }
  return 4;
}

}  // namespace

bool supportsKinds(PrimitiveKind a, PrimitiveKind b, const IntersectionSettings& s) {
  if (rank(a) > rank(b)) std::swap(a, b);
  using K = PrimitiveKind;
  if (a == K::box) return true;
  if (a == K::sphere) return b != K::triangle || s.useSphereTriangle;
  if (a == K::point && b == K::point) return s.usePointPoint;
  if (a == K::point && b == K::line) return s.useLinePoint;
  if (a == K::point && b == K::triangle) return true;
  if (a == K::line && b == K::line) return s.useLineLine;
  if (a == K::triangle && b == K::triangle) return s.triangleTriangle;
  return false;  // line-triangle: through their points and lines
}

void intersectModels(const CollisionModel& first, const CollisionModel& second,
                     std::span<const PrimitivePair> candidates, const IntersectionSettings& s,
                     std::vector<Contact>& contacts) {
  const CollisionGeometry &g1 = first.geometry(), &g2 = second.geometry();
  if (!supportsKinds(g1.kind, g2.kind, s)) return;
  const bool swap = rank(g1.kind) > rank(g2.kind);
  const Side A{swap ? g2 : g1, (swap ? second : first).d_contactDistance.value(),
               (swap ? second : first).d_bothSide.value()};
  const Side B{swap ? g1 : g2, (swap ? first : second).d_contactDistance.value(),
               (swap ? first : second).d_bothSide.value()};
  const bool oneState = first.state() == second.state();
  const double limit = s.alarmDistance + A.thickness + B.thickness;
  auto emit = [&](const Contact& c) { contacts.push_back(swap ? flipped(c) : c); };

  // One loop per kind pair, the test inlined in it (no indirect call per pair).
  auto run = [&](auto&& test) {
    Contact c;
    for (const PrimitivePair& pair : candidates) {
      const std::uint32_t i = swap ? pair.second : pair.first;
      const std::uint32_t j = swap ? pair.first : pair.second;
      if (oneState && shareVertex(A.g, i, B.g, j)) continue;
      test(i, j, c);
    }
  };
  using K = PrimitiveKind;
  auto with = [&](auto pairTest) {
    run([&](std::uint32_t i, std::uint32_t j, Contact& c) {
      if (pairTest(A, i, B, j, s, limit, c)) emit(c);
    });
  };
  if (A.g.kind == K::box) {
    // GJK/EPA (BoxIntersection.h): up to 8 contacts per pair; LocalMinDistance filters the
    // points and segments of a surface as it does against the other primitives.
    const bool filter = s.localMinimum && (B.g.kind == K::point || B.g.kind == K::line);
    run([&](std::uint32_t i, std::uint32_t j, Contact&) {
      std::array<Contact, kMaxBoxContacts> found;
      const int n = intersectBox(A.g, i, B.g, j, B.bothSide, limit, found);
      for (int k = 0; k < n; ++k) {
        const Contact& c = found[k];
        if (filter && !isLocalMinimum(B.g, j, c.point[1], c.point[0] - c.point[1], s.angleCone))
          continue;
        emit(c);
      }
    });
  } else if (A.g.kind == K::sphere)
    with([](auto&&... a) { return spherePrimitive(a...); });
  else if (A.g.kind == K::point && B.g.kind == K::point)
    with([](auto&&... a) { return pointPoint(a...); });
  else if (A.g.kind == K::point && B.g.kind == K::line)
    with([](auto&&... a) { return pointLine(a...); });
  else if (A.g.kind == K::point && B.g.kind == K::triangle)
    with([](auto&&... a) { return pointTriangle(a...); });
  else if (A.g.kind == K::line && B.g.kind == K::line)
    with([](auto&&... a) { return lineLine(a...); });
  else
    run([&](std::uint32_t i, std::uint32_t j, Contact&) {
      triangleTriangle(A, i, B, j, limit, s.useLineLine, emit);
    });
}

}  // namespace stroma::collision
