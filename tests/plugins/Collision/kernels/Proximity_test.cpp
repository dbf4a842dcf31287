// SPDX-License-Identifier: MIT
// The exact proximity primitives (plugins/Collision/kernels/Proximity.h): closest point on a
// triangle and on a segment, closest points of two segments, and the axis-aligned box.
//
// Random cases (fixed seeds, generic and nearly degenerate) are checked three ways: the contract
// (the point lies on the primitive, distance = |difference|), a long-double reference written
// independently (every candidate of the minimisation: the interior stationary point when it is
// inside, and all edges or endpoint queries), and a dense sampling of the primitive (no sample is
// closer than the result, and the result is within the sampling resolution of the nearest
// sample). Exact cases cover each Voronoi region of a triangle, crossing, parallel and collinear
// segments, and zero-length or zero-area primitives.
#include "Collision/kernels/Proximity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace stroma::collision {
namespace {

// ---------------------------------------------------------------------------------------------
// Long-double reference, written from the minimisation problems without the kernel's case
// analysis: the minimum over every candidate point that lies on the primitive.

struct LongVec {
  long double x, y, z;
};
LongVec toLong(const Vec3d& v) { return {v.x(), v.y(), v.z()}; }
LongVec operator-(const LongVec& a, const LongVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
LongVec operator+(const LongVec& a, const LongVec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
LongVec operator*(long double s, const LongVec& a) { return {s * a.x, s * a.y, s * a.z}; }
long double dot(const LongVec& a, const LongVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
LongVec cross(const LongVec& a, const LongVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
long double norm(const LongVec& a) { return std::sqrt(dot(a, a)); }

long double referencePointSegment(const LongVec& p, const LongVec& a, const LongVec& b) {
  const LongVec d = b - a;
  const long double dd = dot(d, d);
  long double t = dd > 0 ? dot(p - a, d) / dd : 0;
  t = std::clamp(t, 0.0L, 1.0L);
  return norm(p - (a + t * d));
}

// Minimum of the three edges and, when the foot of p on the plane is inside, the height of p.
// The plane is spanned by an orthonormal frame built on the longest edge (e along it, m towards
// the third vertex, Gram-Schmidt twice), where the inside test is in two dimensions: for a thin
// triangle the frame's rounding only turns it about its longest edge.
long double referencePointTriangle(const Vec3d& pd, const Vec3d& ad, const Vec3d& bd,
                                   const Vec3d& cd) {
  LongVec v[3] = {toLong(ad), toLong(bd), toLong(cd)};
  const LongVec p = toLong(pd);
  long double best =
      std::min({referencePointSegment(p, v[0], v[1]), referencePointSegment(p, v[1], v[2]),
                referencePointSegment(p, v[2], v[0])});
  while (norm(v[1] - v[0]) < std::max(norm(v[2] - v[1]), norm(v[0] - v[2])))
    std::rotate(v, v + 1, v + 3);
  const LongVec &a = v[0], &b = v[1], &c = v[2];
  const long double length = norm(b - a);
  if (length == 0) return best;
  const LongVec e = (1 / length) * (b - a);
  LongVec m = (c - a) - dot(c - a, e) * e;
  m = m - dot(m, e) * e;
  if (norm(m) == 0) return best;
  m = (1 / norm(m)) * m;
  const LongVec n = cross(e, m);
  const long double x = dot(p - a, e), y = dot(p - a, m), xc = dot(c - a, e), yc = dot(c - a, m);
  // Inside the triangle (0, 0), (length, 0), (xc, yc) of the plane (counter-clockwise: yc > 0).
  if (y >= 0 && (xc - length) * y - yc * (x - length) >= 0 && yc * (x - xc) - xc * (y - yc) >= 0)
    best = std::min(best, std::abs(dot(p - a, n)));
  return best;
}

// Minimum of the closest points of the two lines (when on both segments, then polished) and of
// the four endpoint queries.
long double referenceSegmentSegment(const Vec3d& p0d, const Vec3d& p1d, const Vec3d& q0d,
                                    const Vec3d& q1d) {
  const LongVec p0 = toLong(p0d), p1 = toLong(p1d), q0 = toLong(q0d), q1 = toLong(q1d);
  long double best =
      std::min({referencePointSegment(p0, q0, q1), referencePointSegment(p1, q0, q1),
                referencePointSegment(q0, p0, p1), referencePointSegment(q1, p0, p1)});
  const LongVec d1 = p1 - p0, d2 = q1 - q0, r = q0 - p0, n = cross(d1, d2);
  const long double nn = dot(n, n);
  if (nn > 0) {
    long double s = dot(cross(r, d2), n) / nn, t = dot(cross(r, d1), n) / nn;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
      // Polish by exact minimisation in t, then in s, then in t (each step lowers f and keeps
      // the pair on the segments): for nearly parallel lines s and t above are far less
      // accurate than the distance they give.
      const auto bestT = [&](long double onFirst) {
        return std::clamp(dot((p0 + onFirst * d1) - q0, d2) / dot(d2, d2), 0.0L, 1.0L);
      };
      const auto bestS = [&](long double onSecond) {
        return std::clamp(dot((q0 + onSecond * d2) - p0, d1) / dot(d1, d1), 0.0L, 1.0L);
      };
      t = bestT(s);
      s = bestS(t);
      t = bestT(s);
      best = std::min(best, norm((p0 + s * d1) - (q0 + t * d2)));
    }
  }
  return best;
}

// ---------------------------------------------------------------------------------------------
// Random inputs.

class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(engine_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<>(lo, hi)(engine_); }
  Vec3d point(double halfWidth) {
    return {uniform(-halfWidth, halfWidth), uniform(-halfWidth, halfWidth),
            uniform(-halfWidth, halfWidth)};
  }
  Vec3d unit() {
    for (;;) {
      const Vec3d v = point(1);
      if (v.squaredNorm() > 1e-4 && v.squaredNorm() <= 1) return v.normalized();
    }
  }

 private:
  std::mt19937_64 engine_;
};

// A unit vector orthogonal to d (d non-zero).
Vec3d orthogonalTo(const Vec3d& d, Random& random) {
  for (;;) {
    const Vec3d v = random.unit().cross(d);
    if (v.squaredNorm() > 1e-6 * d.squaredNorm()) return v.normalized();
  }
}

double maxNorm(std::initializer_list<Vec3d> points) {
  double m = 0;
  for (const Vec3d& x : points) m = std::max(m, x.norm());
  return m;
}

// A query point and a triangle; `relativeHeight` is the height over the longest edge divided by
// that edge (0 for a flat triangle), which sets the stated tolerance.
struct TriangleCase {
  Vec3d p, a, b, c;
  double relativeHeight;
  std::string kind;
};

double relativeHeightOf(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const double longest =
      std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return longest > 0 ? (b - a).cross(c - a).norm() / longest : 0;
}

// Case `index` cycles through the shapes: generic, slivers of relative height 1e-1 .. 1e-15 and
// 0, two coincident vertices, three coincident vertices, a needle (one edge 1e-9 long), and a
// generic triangle far from the origin. The query point is random around the triangle, or in
// its plane, or on a vertex or an edge, or within 1 .. 1e-12 of a point of the triangle.
TriangleCase makeTriangleCase(Random& random, int index) {
  TriangleCase k;
  k.a = random.point(1);
  k.b = random.point(1);
  k.c = random.point(1);
  switch (index % 6) {
    case 0:
      k.kind = "generic";
      break;
    case 1: {
      const double h = random.integer(0, 15) == 0 ? 0 : std::pow(10.0, -random.integer(1, 15));
      const Vec3d ab = k.b - k.a;
      k.c = k.a + random.uniform(-0.5, 1.5) * ab + h * ab.norm() * orthogonalTo(ab, random);
      k.kind = "sliver";
      break;
    }
    case 2:
      (random.integer(0, 1) ? k.b : k.c) = k.a;
      k.kind = "two coincident vertices";
      break;
    case 3:
      k.b = k.c = k.a;
      k.kind = "three coincident vertices";
      break;
    case 4:
      k.b = k.a + 1e-9 * random.unit();
      k.kind = "needle";
      break;
    default: {
      const Vec3d offset = 1e3 * random.unit();
      k.a += offset;
      k.b += offset;
      k.c += offset;
      k.kind = "far from the origin";
    }
  }
  const Vec3d centre = (k.a + k.b + k.c) / 3;
  switch (random.integer(0, 6)) {
    case 0: {  // in the plane, inside or outside
      const double v = random.uniform(-1, 2), w = random.uniform(-1, 2);
      k.p = k.a + v * (k.b - k.a) + w * (k.c - k.a);
      break;
    }
    case 1:
      k.p = random.integer(0, 1) ? k.b : k.c;
      break;
    case 2:
      k.p = k.a + random.uniform(0, 1) * (k.c - k.a);
      break;
    case 3: {  // near a point of the triangle, 1 to 1e-12 away
      const double v = random.uniform(0, 1), w = random.uniform(0, 1 - v);
      k.p = k.a + v * (k.b - k.a) + w * (k.c - k.a) +
            std::pow(10.0, -random.integer(0, 12)) * random.unit();
      break;
    }
    default:
      k.p = centre + random.point(2);
  }
  k.relativeHeight = relativeHeightOf(k.a, k.b, k.c);
  return k;
}

// Tolerance on the distance, relative to the size of the coordinates (maxNorm + 1). Measured
// with the seeds below: 2.9e-16 for every kind, slivers of any relative height included.
constexpr double kTriangleTolerance = 1e-15;

double triangleTolerance(const TriangleCase& k) {
  return kTriangleTolerance * (maxNorm({k.p, k.a, k.b, k.c}) + 1);
}

// The contract of a point-triangle result.
void expectValidTriangleResult(const PointTriangleResult& r, const TriangleCase& k) {
  const double size = maxNorm({k.p, k.a, k.b, k.c}) + 1;
  ASSERT_TRUE(r.closest.allFinite() && r.barycentric.allFinite() && std::isfinite(r.distance));
  EXPECT_GE(r.barycentric.minCoeff(), 0.0);
  EXPECT_NEAR(r.barycentric.sum(), 1.0, 4e-16);
  const Vec3d combination =
      r.barycentric[0] * k.a + r.barycentric[1] * k.b + r.barycentric[2] * k.c;
  EXPECT_LE((combination - r.closest).norm(), 1e-15 * size);
  EXPECT_DOUBLE_EQ(r.distance, (k.p - r.closest).norm());
}

// ---------------------------------------------------------------------------------------------
// Point-triangle.

TEST(ClosestPointOnTriangle, MatchesLongDoubleReferenceOnRandomAndDegenerateTriangles) {
  Random random(20240515);
  double worstGeneric = 0, worstSliver = 0;
  for (int i = 0; i < 200000; ++i) {
    const TriangleCase k = makeTriangleCase(random, i);
    const PointTriangleResult r = closestPointOnTriangle(k.p, k.a, k.b, k.c);
    expectValidTriangleResult(r, k);
    const double reference = double(referencePointTriangle(k.p, k.a, k.b, k.c));
    const double error = std::abs(r.distance - reference);
    const double size = maxNorm({k.p, k.a, k.b, k.c}) + 1;
    (k.kind == "sliver" ? worstSliver : worstGeneric) =
        std::max(k.kind == "sliver" ? worstSliver : worstGeneric, error / size);
    ASSERT_LE(error, triangleTolerance(k))
        << k.kind << " case " << i << ", relative height " << k.relativeHeight << ", distance "
        << r.distance << ", reference " << reference;
  }
  std::printf(
      "point-triangle: largest |distance - reference| / size: %.3g (slivers), %.3g "
      "(others); tolerance %.3g\n",
      worstSliver, worstGeneric, kTriangleTolerance);
}

TEST(ClosestPointOnTriangle, NoSampleOfTheTriangleIsCloser) {
  Random random(7);
  constexpr int kGrid = 200;  // samples a + (i/N) ab + (j/N) ac, i + j <= N
  for (int i = 0; i < 1500; ++i) {
    const TriangleCase k = makeTriangleCase(random, i);
    const PointTriangleResult r = closestPointOnTriangle(k.p, k.a, k.b, k.c);
    expectValidTriangleResult(r, k);
    const Vec3d ab = k.b - k.a, ac = k.c - k.a;
    double sampled = std::numeric_limits<double>::infinity();
    for (int u = 0; u <= kGrid; ++u)
      for (int v = 0; u + v <= kGrid; ++v) {
        const Vec3d x = k.a + (double(u) / kGrid) * ab + (double(v) / kGrid) * ac;
        sampled = std::min(sampled, (k.p - x).norm());
      }
    // Every point of the triangle is within longest / N of a sample.
    const double resolution =
        std::max({ab.norm(), ac.norm(), (k.c - k.b).norm()}) / kGrid + 1e-15 * maxNorm({k.a});
    EXPECT_LE(r.distance, sampled + triangleTolerance(k)) << k.kind << " case " << i;
    EXPECT_LE(sampled, r.distance + resolution + triangleTolerance(k)) << k.kind << " case " << i;
  }
}

// Triangle a = (0,0,0), b = (2,0,0), c = (0,2,0) in the plane z = 0; the seven Voronoi regions.
struct RegionCase {
  const char* region;
  Vec3d p, closest, barycentric;
};

TEST(ClosestPointOnTriangle, EachVoronoiRegion) {
  const Vec3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  const RegionCase cases[] = {
      {"face", {0.5, 0.5, 3}, {0.5, 0.5, 0}, {0.5, 0.25, 0.25}},
      {"face, below", {0.5, 1, -2}, {0.5, 1, 0}, {0.25, 0.25, 0.5}},
      {"vertex a", {-1, -2, 1}, {0, 0, 0}, {1, 0, 0}},
      {"vertex b", {3, -1, 0.5}, {2, 0, 0}, {0, 1, 0}},
      {"vertex c", {-0.5, 4, -1}, {0, 2, 0}, {0, 0, 1}},
      {"edge ab", {1.5, -3, 2}, {1.5, 0, 0}, {0.25, 0.75, 0}},
      {"edge bc", {2, 2, 1}, {1, 1, 0}, {0, 0.5, 0.5}},
      {"edge ca", {-4, 0.5, 0}, {0, 0.5, 0}, {0.75, 0, 0.25}},
      // Region limits: the normal of an edge through its end.
      {"edge ab at b", {2, -1, 0}, {2, 0, 0}, {0, 1, 0}},
      {"beyond b along ab", {3, 0, 0}, {2, 0, 0}, {0, 1, 0}},
  };
  for (const RegionCase& k : cases) {
    const PointTriangleResult r = closestPointOnTriangle(k.p, a, b, c);
    EXPECT_LE((r.closest - k.closest).norm(), 1e-15) << k.region;
    EXPECT_LE((r.barycentric - k.barycentric).norm(), 1e-15) << k.region;
    EXPECT_NEAR(r.distance, (k.p - k.closest).norm(), 1e-15) << k.region;
  }
}

TEST(ClosestPointOnTriangle, AboveTheInteriorIsTheHeightAndTheFoot) {
  // A tilted triangle; p = foot + h * unit normal.
  const Vec3d a(1, 2, 3), b(4, 2.5, 2), c(2, 5, 4);
  const Vec3d normal = (b - a).cross(c - a).normalized();
  const Vec3d barycentric(0.2, 0.3, 0.5);
  const Vec3d foot = barycentric[0] * a + barycentric[1] * b + barycentric[2] * c;
  for (double h : {0.0, 1e-12, 0.7, -2.5, 1e3}) {
    const PointTriangleResult r = closestPointOnTriangle(foot + h * normal, a, b, c);
    EXPECT_NEAR(r.distance, std::abs(h), 1e-14 * (1 + std::abs(h))) << h;
    EXPECT_LE((r.barycentric - barycentric).norm(), 1e-14 * (1 + std::abs(h))) << h;
    EXPECT_LE((r.closest - foot).norm(), 1e-13 * (1 + std::abs(h))) << h;
  }
}

TEST(ClosestPointOnTriangle, PointsOnTheTriangleAreAtDistanceZero) {
  const Vec3d a(0.1, -0.3, 0.7), b(1.3, 0.2, -0.4), c(-0.6, 1.1, 0.5);
  // The vertices, edge and interior points, to rounding.
  const Vec3d vertices[] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const PointTriangleResult r = closestPointOnTriangle(vertices[i], a, b, c);
    EXPECT_LE(r.distance, 1e-15) << i;
    EXPECT_LE((r.barycentric - Vec3d::Unit(i)).norm(), 1e-15) << i;
  }
  for (const Vec3d& x : {Vec3d(0.5 * (a + b)), Vec3d(0.25 * b + 0.75 * c), Vec3d((a + b + c) / 3)})
    EXPECT_LE(closestPointOnTriangle(x, a, b, c).distance, 1e-15);
}

TEST(ClosestPointOnTriangle, ZeroAreaTrianglesUseTheirEdges) {
  // Collinear vertices: the longest edge is a to c, b lies between.
  const Vec3d a(0, 0, 0), b(1, 0, 0), c(3, 0, 0);
  PointTriangleResult r = closestPointOnTriangle(Vec3d(2, 1, 0), a, b, c);
  EXPECT_EQ(r.closest, Vec3d(2, 0, 0));
  EXPECT_EQ(r.distance, 1);
  r = closestPointOnTriangle(Vec3d(-2, 0, 0), a, b, c);  // beyond a, on the line
  EXPECT_EQ(r.closest, a);
  EXPECT_EQ(r.distance, 2);
  r = closestPointOnTriangle(Vec3d(2.5, 0, 0), a, b, c);  // on the triangle
  EXPECT_EQ(r.distance, 0);
  // Two coincident vertices: the remaining edge.
  r = closestPointOnTriangle(Vec3d(0.5, 0, 2), a, a, c);
  EXPECT_EQ(r.closest, Vec3d(0.5, 0, 0));
  EXPECT_EQ(r.distance, 2);
  EXPECT_NEAR(r.barycentric.sum(), 1, 1e-16);
  // Three coincident vertices: the point.
  r = closestPointOnTriangle(Vec3d(3, 4, 0), b, b, b);
  EXPECT_EQ(r.closest, b);
  EXPECT_EQ(r.barycentric, Vec3d(1, 0, 0));
  EXPECT_EQ(r.distance, std::sqrt(4.0 + 16.0));
}

TEST(ClosestPointOnTriangle, DoesNotDependOnTheVertexOrder) {
  Random random(11);
  for (int i = 0; i < 2000; ++i) {
    const TriangleCase k = makeTriangleCase(random, i);
    const double d = closestPointOnTriangle(k.p, k.a, k.b, k.c).distance;
    const double tolerance = 2 * triangleTolerance(k);  // two results, each within its own
    EXPECT_NEAR(closestPointOnTriangle(k.p, k.b, k.c, k.a).distance, d, tolerance) << k.kind;
    EXPECT_NEAR(closestPointOnTriangle(k.p, k.c, k.b, k.a).distance, d, tolerance) << k.kind;
  }
}

// ---------------------------------------------------------------------------------------------
// Point-segment.

void expectValidSegmentResult(const PointSegmentResult& r, const Vec3d& p, const Vec3d& a,
                              const Vec3d& b) {
  ASSERT_TRUE(r.closest.allFinite() && std::isfinite(r.t) && std::isfinite(r.distance));
  EXPECT_GE(r.t, 0.0);
  EXPECT_LE(r.t, 1.0);
  EXPECT_LE((a + r.t * (b - a) - r.closest).norm(), 1e-15 * (maxNorm({a, b}) + 1));
  EXPECT_DOUBLE_EQ(r.distance, (p - r.closest).norm());
}

TEST(ClosestPointOnSegment, MatchesReferenceAndDenseSampling) {
  Random random(3);
  constexpr int kSamples = 2000;
  double worst = 0;
  for (int i = 0; i < 5000; ++i) {
    Vec3d a = random.point(1), b = random.point(1);
    if (i % 5 == 1) b = a;                                                            // zero length
    if (i % 5 == 2) b = a + std::pow(10.0, -random.integer(5, 200)) * random.unit();  // tiny
    const Vec3d p = i % 7 == 0 ? Vec3d(a + random.uniform(-1, 2) * (b - a)) : random.point(2);
    const PointSegmentResult r = closestPointOnSegment(p, a, b);
    expectValidSegmentResult(r, p, a, b);
    const double size = maxNorm({p, a, b}) + 1;
    const double reference = double(referencePointSegment(toLong(p), toLong(a), toLong(b)));
    worst = std::max(worst, std::abs(r.distance - reference) / size);
    EXPECT_NEAR(r.distance, reference, 1e-15 * size);
    double sampled = std::numeric_limits<double>::infinity();
    for (int j = 0; j <= kSamples; ++j)
      sampled = std::min(sampled, (p - (a + (double(j) / kSamples) * (b - a))).norm());
    EXPECT_LE(r.distance, sampled + 1e-15 * size);
    EXPECT_LE(sampled, r.distance + (b - a).norm() / kSamples + 1e-15 * size);
  }
  std::printf("point-segment: largest |distance - reference| / size: %.3g; tolerance 1e-15\n",
              worst);
}

TEST(ClosestPointOnSegment, ExactCases) {
  const Vec3d a(1, 1, 1), b(3, 1, 1);
  PointSegmentResult r = closestPointOnSegment(Vec3d(2.5, 4, 1), a, b);  // interior
  EXPECT_EQ(r.t, 0.75);
  EXPECT_EQ(r.closest, Vec3d(2.5, 1, 1));
  EXPECT_EQ(r.distance, 3);
  r = closestPointOnSegment(Vec3d(-1, 1, 2), a, b);  // beyond a
  EXPECT_EQ(r.t, 0);
  EXPECT_EQ(r.closest, a);
  EXPECT_EQ(r.distance, std::sqrt(5.0));
  r = closestPointOnSegment(Vec3d(7, 4, 1), a, b);  // beyond b: exactly b
  EXPECT_EQ(r.t, 1);
  EXPECT_EQ(r.closest, b);
  EXPECT_EQ(r.distance, 5);
  r = closestPointOnSegment(Vec3d(2, 1, 1), a, b);  // on the segment
  EXPECT_EQ(r.distance, 0);
  r = closestPointOnSegment(Vec3d(1, 5, 4), a, a);  // zero length
  EXPECT_EQ(r.t, 0);
  EXPECT_EQ(r.closest, a);
  EXPECT_EQ(r.distance, 5);
  // A length whose square underflows: the point a. A length whose square is subnormal, with a
  // quotient that overflows: clamped to b, finite.
  r = closestPointOnSegment(Vec3d(0, 1, 1), Vec3d::Zero(), Vec3d(1e-170, 0, 0));
  EXPECT_EQ(r.t, 0);
  EXPECT_EQ(r.closest, Vec3d::Zero());
  r = closestPointOnSegment(Vec3d(1e150, 1, 1), Vec3d::Zero(), Vec3d(1e-160, 0, 0));
  EXPECT_EQ(r.t, 1);
  EXPECT_EQ(r.closest, Vec3d(1e-160, 0, 0));
  EXPECT_TRUE(std::isfinite(r.distance));
}

// ---------------------------------------------------------------------------------------------
// Segment-segment.

void expectValidPair(const SegmentSegmentResult& r, const Vec3d& p0, const Vec3d& p1,
                     const Vec3d& q0, const Vec3d& q1) {
  ASSERT_TRUE(r.closestOnFirst.allFinite() && r.closestOnSecond.allFinite() && std::isfinite(r.s) &&
              std::isfinite(r.t) && std::isfinite(r.distance));
  EXPECT_GE(r.s, 0.0);
  EXPECT_LE(r.s, 1.0);
  EXPECT_GE(r.t, 0.0);
  EXPECT_LE(r.t, 1.0);
  const double size = maxNorm({p0, p1, q0, q1}) + 1;
  EXPECT_LE((p0 + r.s * (p1 - p0) - r.closestOnFirst).norm(), 1e-15 * size);
  EXPECT_LE((q0 + r.t * (q1 - q0) - r.closestOnSecond).norm(), 1e-15 * size);
  EXPECT_DOUBLE_EQ(r.distance, (r.closestOnFirst - r.closestOnSecond).norm());
}

struct SegmentPairCase {
  Vec3d p0, p1, q0, q1;
  std::string kind;
};

// Case `index` cycles through: generic, nearly parallel (angle 1e-1 .. 1e-16 rad, and exactly
// parallel), collinear, crossing (the lines meet inside both, or pass 1 .. 1e-12 apart), one
// zero-length segment, both zero-length, and generic far from the origin.
SegmentPairCase makeSegmentPair(Random& random, int index) {
  SegmentPairCase k{random.point(1), random.point(1), random.point(1), random.point(1), ""};
  const Vec3d d = k.p1 - k.p0;
  switch (index % 7) {
    case 0:
      k.kind = "generic";
      break;
    case 1: {
      const double angle = random.integer(0, 16) == 0 ? 0 : std::pow(10.0, -random.integer(1, 16));
      const Vec3d direction =
          std::cos(angle) * d.normalized() + std::sin(angle) * orthogonalTo(d, random);
      // Apart, or crossing the first segment at x.
      const Vec3d x = k.p0 + random.uniform(0, 1) * d;
      const Vec3d apart = random.uniform(0, 0.5) * orthogonalTo(d, random);
      k.q0 = x - random.uniform(0, 1) * d.norm() * direction +
             (random.integer(0, 1) ? apart : Vec3d::Zero());
      k.q1 = x + random.uniform(0, 1) * d.norm() * direction;
      k.kind = "nearly parallel";
      break;
    }
    case 2:
      k.q0 = k.p0 + random.uniform(-1, 2) * d;
      k.q1 = k.p0 + random.uniform(-1, 2) * d;
      k.kind = "collinear";
      break;
    case 3: {  // crossing, or passing 1 .. 1e-12 away
      const Vec3d x =
          k.p0 + random.uniform(0, 1) * d +
          (random.integer(0, 1) ? 0 : std::pow(10.0, -random.integer(0, 12))) * random.unit();
      const Vec3d e = random.unit();
      k.q0 = x - random.uniform(0, 1) * e;
      k.q1 = x + random.uniform(0, 1) * e;
      k.kind = "crossing";
      break;
    }
    case 4:
      if (random.integer(0, 1))
        k.p1 = k.p0;
      else
        k.q1 = k.q0;
      k.kind = "one zero-length";
      break;
    case 5:
      k.p1 = k.p0;
      k.q1 = k.q0;
      k.kind = "both zero-length";
      break;
    default: {
      const Vec3d offset = 1e3 * random.unit();
      k.p0 += offset;
      k.p1 += offset;
      k.q0 += offset;
      k.q1 += offset;
      k.kind = "far from the origin";
    }
  }
  return k;
}

// Tolerance on the distance, relative to the size of the coordinates (maxNorm + 1). Measured
// with the seeds below: 3.4e-16 for every kind, nearly parallel included (the pair stays on the
// valley of f).
constexpr double kSegmentTolerance = 1e-15;

TEST(ClosestPointsOfSegments, MatchesLongDoubleReferenceOnRandomAndDegeneratePairs) {
  Random random(99);
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const SegmentPairCase k = makeSegmentPair(random, i);
    const SegmentSegmentResult r = closestPointsOfSegments(k.p0, k.p1, k.q0, k.q1);
    expectValidPair(r, k.p0, k.p1, k.q0, k.q1);
    const double reference = double(referenceSegmentSegment(k.p0, k.p1, k.q0, k.q1));
    const double size = maxNorm({k.p0, k.p1, k.q0, k.q1}) + 1;
    worst = std::max(worst, std::abs(r.distance - reference) / size);
    ASSERT_NEAR(r.distance, reference, kSegmentTolerance * size)
        << k.kind << " case " << i << ", s " << r.s << ", t " << r.t;
  }
  std::printf("segment-segment: largest |distance - reference| / size: %.3g; tolerance %.3g\n",
              worst, kSegmentTolerance);
}

TEST(ClosestPointsOfSegments, NoSampledPairIsCloser) {
  Random random(5);
  constexpr int kSamples = 300;
  for (int i = 0; i < 350; ++i) {
    const SegmentPairCase k = makeSegmentPair(random, i);
    const SegmentSegmentResult r = closestPointsOfSegments(k.p0, k.p1, k.q0, k.q1);
    expectValidPair(r, k.p0, k.p1, k.q0, k.q1);
    const Vec3d d1 = k.p1 - k.p0, d2 = k.q1 - k.q0;
    double sampled = std::numeric_limits<double>::infinity();
    for (int u = 0; u <= kSamples; ++u) {
      const Vec3d x = k.p0 + (double(u) / kSamples) * d1;
      for (int v = 0; v <= kSamples; ++v)
        sampled = std::min(sampled, (x - (k.q0 + (double(v) / kSamples) * d2)).norm());
    }
    const double size = maxNorm({k.p0, k.p1, k.q0, k.q1}) + 1;
    const double resolution = (d1.norm() + d2.norm()) / kSamples;
    EXPECT_LE(r.distance, sampled + kSegmentTolerance * size) << k.kind << " case " << i;
    EXPECT_LE(sampled, r.distance + resolution + kSegmentTolerance * size)
        << k.kind << " case " << i;
  }
}

TEST(ClosestPointsOfSegments, CrossingSegmentsAreAtDistanceZero) {
  const SegmentSegmentResult r =
      closestPointsOfSegments(Vec3d(-1, 0, 0), Vec3d(3, 0, 0), Vec3d(0, -2, 0), Vec3d(0, 2, 0));
  EXPECT_EQ(r.distance, 0);
  EXPECT_EQ(r.s, 0.25);
  EXPECT_EQ(r.t, 0.5);
  EXPECT_EQ(r.closestOnFirst, Vec3d::Zero());
  // An endpoint touching the other segment's interior (a T).
  const SegmentSegmentResult touching =
      closestPointsOfSegments(Vec3d(0, 0, 0), Vec3d(4, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 0, 3));
  EXPECT_EQ(touching.distance, 0);
  EXPECT_EQ(touching.closestOnFirst, Vec3d(1, 0, 0));
}

TEST(ClosestPointsOfSegments, SkewSegments) {
  // The common perpendicular of the lines x-axis and (z = 2, along y) meets both interiors.
  SegmentSegmentResult r =
      closestPointsOfSegments(Vec3d(-1, 0, 0), Vec3d(1, 0, 0), Vec3d(0.5, -1, 2), Vec3d(0.5, 3, 2));
  EXPECT_EQ(r.distance, 2);
  EXPECT_EQ(r.closestOnFirst, Vec3d(0.5, 0, 0));
  EXPECT_EQ(r.closestOnSecond, Vec3d(0.5, 0, 2));
  // Its foot is beyond the second segment's end: the end q0 and its foot on the first.
  r = closestPointsOfSegments(Vec3d(-1, 0, 0), Vec3d(1, 0, 0), Vec3d(0.5, 1, 2), Vec3d(0.5, 3, 2));
  EXPECT_EQ(r.t, 0);
  EXPECT_EQ(r.closestOnFirst, Vec3d(0.5, 0, 0));
  EXPECT_EQ(r.distance, std::sqrt(5.0));
  // Both feet beyond the ends: the two nearest ends.
  r = closestPointsOfSegments(Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(2, 1, 1), Vec3d(2, 5, 1));
  EXPECT_EQ(r.s, 1);
  EXPECT_EQ(r.t, 0);
  EXPECT_EQ(r.distance, std::sqrt(3.0));
}

TEST(ClosestPointsOfSegments, ParallelSegmentsGiveTheSeparationAndAValidPair) {
  // Overlapping in projection: distance = separation, any pair with difference orthogonal.
  const Vec3d offset(0, 3, 4);  // separation 5
  const Vec3d p0(0, 0, 0), p1(4, 0, 0);
  for (const auto& [q0, q1] :
       {std::pair{Vec3d(1, 0, 0), Vec3d(6, 0, 0)}, std::pair{Vec3d(6, 0, 0), Vec3d(1, 0, 0)},
        std::pair{Vec3d(-2, 0, 0), Vec3d(9, 0, 0)}}) {
    const SegmentSegmentResult r = closestPointsOfSegments(p0, p1, q0 + offset, q1 + offset);
    expectValidPair(r, p0, p1, q0 + offset, q1 + offset);
    EXPECT_NEAR(r.distance, 5, 1e-15);
    EXPECT_NEAR((r.closestOnSecond - r.closestOnFirst - offset).norm(), 0, 1e-15);
  }
  // Disjoint in projection: the two nearest ends.
  const SegmentSegmentResult r =
      closestPointsOfSegments(p0, p1, Vec3d(6, 0, 0) + offset, Vec3d(9, 0, 0) + offset);
  EXPECT_EQ(r.closestOnFirst, p1);
  EXPECT_EQ(r.closestOnSecond, Vec3d(6, 3, 4));
  EXPECT_EQ(r.distance, std::sqrt(4.0 + 25.0));
}

TEST(ClosestPointsOfSegments, CollinearSegments) {
  const Vec3d p0(1, 1, 1), p1(1, 1, 5);
  // Overlapping: a common point at distance zero.
  SegmentSegmentResult r = closestPointsOfSegments(p0, p1, Vec3d(1, 1, 4), Vec3d(1, 1, 9));
  EXPECT_EQ(r.distance, 0);
  EXPECT_EQ(r.closestOnFirst, r.closestOnSecond);
  r = closestPointsOfSegments(p0, p1, Vec3d(1, 1, 2), Vec3d(1, 1, 3));  // contained
  EXPECT_EQ(r.distance, 0);
  // Disjoint: the gap between the facing ends.
  r = closestPointsOfSegments(p0, p1, Vec3d(1, 1, 9), Vec3d(1, 1, 7));
  EXPECT_EQ(r.distance, 2);
  EXPECT_EQ(r.closestOnFirst, p1);
  EXPECT_EQ(r.closestOnSecond, Vec3d(1, 1, 7));
  EXPECT_EQ(r.t, 1);
}

TEST(ClosestPointsOfSegments, ZeroLengthSegments) {
  const Vec3d p(0, 3, 0), a(-1, 0, 0), b(1, 0, 0);
  SegmentSegmentResult r = closestPointsOfSegments(p, p, a, b);  // point against segment
  EXPECT_EQ(r.s, 0);
  EXPECT_EQ(r.t, 0.5);
  EXPECT_EQ(r.closestOnFirst, p);
  EXPECT_EQ(r.closestOnSecond, Vec3d::Zero());
  EXPECT_EQ(r.distance, 3);
  r = closestPointsOfSegments(a, b, p, p);  // segment against point
  EXPECT_EQ(r.s, 0.5);
  EXPECT_EQ(r.t, 0);
  EXPECT_EQ(r.distance, 3);
  r = closestPointsOfSegments(p, p, a, a);  // two points
  EXPECT_EQ(r.s, 0);
  EXPECT_EQ(r.t, 0);
  EXPECT_EQ(r.distance, std::sqrt(10.0));
}

TEST(ClosestPointsOfSegments, SymmetricInTheSegmentsAndTheirDirections) {
  Random random(17);
  for (int i = 0; i < 5000; ++i) {
    const SegmentPairCase k = makeSegmentPair(random, i);
    const double size = maxNorm({k.p0, k.p1, k.q0, k.q1}) + 1;
    const SegmentSegmentResult r = closestPointsOfSegments(k.p0, k.p1, k.q0, k.q1);
    const SegmentSegmentResult swapped = closestPointsOfSegments(k.q0, k.q1, k.p0, k.p1);
    const SegmentSegmentResult reversed = closestPointsOfSegments(k.p1, k.p0, k.q1, k.q0);
    EXPECT_NEAR(swapped.distance, r.distance, 2 * kSegmentTolerance * size) << k.kind;
    EXPECT_NEAR(reversed.distance, r.distance, 2 * kSegmentTolerance * size) << k.kind;
  }
}

// ---------------------------------------------------------------------------------------------
// Aabb.

TEST(Aabb, DefaultIsEmptyAndOverlapsNothing) {
  const Aabb empty;
  EXPECT_TRUE(empty.empty());
  EXPECT_FALSE(empty.contains(Vec3d::Zero()));
  Aabb all = Aabb::around(Vec3d::Zero());
  all.expand(1e300);
  EXPECT_FALSE(empty.overlaps(all));
  EXPECT_FALSE(all.overlaps(empty));
  EXPECT_FALSE(empty.overlaps(empty));
  Aabb grown;
  grown.expand(2.0);  // a margin keeps an empty box empty
  EXPECT_TRUE(grown.empty());
}

TEST(Aabb, ExpandByPointsAndMargin) {
  Aabb box;
  box.expand(Vec3d(1, -2, 3));
  EXPECT_FALSE(box.empty());
  EXPECT_EQ(box.min, Vec3d(1, -2, 3));
  EXPECT_EQ(box.max, Vec3d(1, -2, 3));
  box.expand(Vec3d(-1, 4, 3.5));
  EXPECT_EQ(box.min, Vec3d(-1, -2, 3));
  EXPECT_EQ(box.max, Vec3d(1, 4, 3.5));
  EXPECT_TRUE(box.contains(Vec3d(0, 0, 3.25)));
  EXPECT_TRUE(box.contains(Vec3d(1, 4, 3)));  // closed: its corners
  EXPECT_FALSE(box.contains(Vec3d(0, 0, 3.6)));
  box.expand(0.5);
  EXPECT_EQ(box.min, Vec3d(-1.5, -2.5, 2.5));
  EXPECT_EQ(box.max, Vec3d(1.5, 4.5, 4));
  box.expand(-0.5);
  EXPECT_EQ(box.min, Vec3d(-1, -2, 3));
  box.expand(-0.3);  // shrunk past its thinnest side (0.5 along z)
  EXPECT_TRUE(box.empty());
}

TEST(Aabb, OverlapsIsClosedAndPerAxis) {
  const Aabb unit{Vec3d(0, 0, 0), Vec3d(1, 1, 1)};
  EXPECT_TRUE(unit.overlaps(unit));
  EXPECT_TRUE(overlaps(unit, unit));  // the free form
  EXPECT_TRUE(unit.overlaps(Aabb{Vec3d(0.5, 0.5, 0.5), Vec3d(2, 2, 2)}));
  EXPECT_TRUE(unit.overlaps(Aabb{Vec3d(0.2, 0.2, 0.2), Vec3d(0.3, 0.3, 0.3)}));  // inside
  EXPECT_TRUE(unit.overlaps(Aabb{Vec3d(1, 1, 1), Vec3d(2, 2, 2)}));              // touching corners
  EXPECT_TRUE(unit.overlaps(Aabb{Vec3d(1, 0, 0), Vec3d(2, 1, 1)}));              // touching faces
  // Separated along one axis only.
  for (int axis = 0; axis < 3; ++axis) {
    Aabb other{Vec3d(0.5, 0.5, 0.5), Vec3d(2, 2, 2)};
    other.min[axis] = 1.5;
    EXPECT_FALSE(unit.overlaps(other)) << axis;
    EXPECT_FALSE(other.overlaps(unit)) << axis;
    EXPECT_FALSE(overlaps(unit, other)) << axis;
    other.expand(0.5);  // within the margin: overlaps
    EXPECT_TRUE(unit.overlaps(other)) << axis;
  }
  // A shrunk, empty box inside the other's range overlaps nothing.
  Aabb shrunk{Vec3d(0.25, 0.25, 0.25), Vec3d(0.75, 0.75, 0.75)};
  shrunk.expand(-0.25);
  EXPECT_FALSE(shrunk.empty());  // a single point
  shrunk.expand(-1e-3);
  EXPECT_TRUE(shrunk.empty());
  EXPECT_FALSE(unit.overlaps(shrunk));
}

TEST(Aabb, MergeHoldsBoth) {
  Aabb box;
  box.merge(Aabb{});  // empty with empty
  EXPECT_TRUE(box.empty());
  box.merge(Aabb{Vec3d(0, 0, 0), Vec3d(1, 1, 1)});
  EXPECT_EQ(box.min, Vec3d(0, 0, 0));
  EXPECT_EQ(box.max, Vec3d(1, 1, 1));
  box.merge(Aabb{Vec3d(-1, 0.5, 0.5), Vec3d(0.5, 3, 0.7)});
  EXPECT_EQ(box.min, Vec3d(-1, 0, 0));
  EXPECT_EQ(box.max, Vec3d(1, 3, 1));
  const Aabb before = box;
  box.merge(Aabb{});
  EXPECT_EQ(box.min, before.min);
  EXPECT_EQ(box.max, before.max);
  // The merge of the boxes of two point sets is the box of their union.
  Random random(23);
  Aabb first, second, all;
  for (int i = 0; i < 100; ++i) {
    const Vec3d x = random.point(5);
    (i % 3 ? first : second).expand(x);
    all.expand(x);
  }
  first.merge(second);
  EXPECT_EQ(first.min, all.min);
  EXPECT_EQ(first.max, all.max);
}

}  // namespace
}  // namespace stroma::collision
