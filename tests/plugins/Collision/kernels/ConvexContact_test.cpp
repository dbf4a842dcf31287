// SPDX-License-Identifier: MIT
// Contacts of oriented boxes by GJK/EPA (plugins/Collision/kernels/ConvexContact): box against
// box, point (a sphere's centre), segment and triangle, separated and interpenetrating, face,
// edge and vertex configurations, against closed forms; every configuration is also turned and
// moved as a whole (the answer must follow). The refinement makes the answers exact to rounding:
// asserted to 1e-12 of the boxes' size, where Bullet's own float answer is off by up to 1e-6
// (measured below, and printed).
#include "Collision/kernels/ConvexContact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "Collision/kernels/Proximity.h"

namespace stroma::collision {
namespace {

constexpr double kExact = 1e-12;  // relative to the primitives' size (about 1 here)

Mat3d rotation(double angle, const Vec3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

OrientedBox box(const Vec3d& center, const Vec3d& half, const Mat3d& R = Mat3d::Identity()) {
  return {center, R, half};
}

// A rigid motion applied to a whole configuration.
struct Motion {
  Mat3d R = Mat3d::Identity();
  Vec3d t = Vec3d::Zero();
  Vec3d point(const Vec3d& x) const { return R * x + t; }
  Vec3d vector(const Vec3d& v) const { return R * v; }
  OrientedBox apply(const OrientedBox& b) const {
    return {point(b.center), R * b.rotation, b.halfExtents};
  }
  ConvexPrimitive apply(const ConvexPrimitive& p) const {
    ConvexPrimitive q = p;
    for (Vec3d& v : q.vertices) v = point(v);
    q.box = apply(p.box);
    return q;
  }
};

std::vector<Motion> motions() {
  std::vector<Motion> m(1);  // the identity
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 4; ++k)
    m.push_back({rotation(std::numbers::pi * u(random), Vec3d(u(random), u(random), u(random))),
                 Vec3d(u(random), u(random), u(random)) * 3});
  return m;
}

// An expected contact point, in the configuration's own frame.
struct Expected {
  Vec3d onFirst, onSecond;
  double distance;
};

// Checks computeConvexContacts(first, second) against the expected normal and points (in any
// order), under every motion of the pair; returns the largest error of Bullet's own distance.
double expectContacts(const ConvexPrimitive& first, const ConvexPrimitive& second, double limit,
                      const Vec3d& normal, const std::vector<Expected>& expected,
                      const char* what) {
  double bulletError = 0;
  for (const Motion& m : motions()) {
    SCOPED_TRACE(what);
    const ConvexPrimitive a = m.apply(first), b = m.apply(second);
    ConvexContacts c;
    const bool found = computeConvexContacts(a, b, limit, c);
    EXPECT_EQ(found, !expected.empty());
    if (expected.empty()) continue;
    EXPECT_LT((c.normal - m.vector(normal)).norm(), kExact) << c.normal.transpose();
    EXPECT_EQ(c.count, int(expected.size()));
    double least = std::numeric_limits<double>::infinity();
    for (const Expected& e : expected) {
      least = std::min(least, e.distance);
      bool matched = false;
      for (int k = 0; k < c.count && !matched; ++k) {
        const ConvexContactPoint& p = c.points[k];
        matched = (p.onFirst - m.point(e.onFirst)).norm() < kExact &&
                  (p.onSecond - m.point(e.onSecond)).norm() < kExact &&
                  std::abs(p.distance - e.distance) < kExact;
      }
      EXPECT_TRUE(matched) << "no contact at " << e.onFirst.transpose() << " / "
                           << e.onSecond.transpose() << " distance " << e.distance;
    }
    for (int k = 0; k < c.count; ++k) {
      const ConvexContactPoint& p = c.points[k];
      EXPECT_LT((p.onSecond - p.onFirst - p.distance * c.normal).norm(), kExact);
    }
    EXPECT_NEAR(c.distance, least, kExact);
    const GjkEpaResult raw = computeGjkEpa(a, b);
    if (raw.status != GjkEpaResult::Status::failed)
      bulletError = std::max(bulletError, std::abs(raw.distance - least));
  }
  return bulletError;
}

ConvexPrimitive boxAt(const Vec3d& c, const Vec3d& h, const Mat3d& R = Mat3d::Identity()) {
  return ConvexPrimitive::orientedBox(box(c, h, R));
}

// The 4 corners of the face z = top of an axis-aligned box of half extents h centred at c,
// against the plane z = plane: Expected{on the plane, corner, corner z - plane} (first: plane).
std::vector<Expected> cornersOverPlane(const Vec3d& c, const Vec3d& h, double plane, bool boxFirst,
                                       const Mat3d& Rz = Mat3d::Identity()) {
  std::vector<Expected> out;
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0}) {
      const Vec3d corner = c + Rz * Vec3d(sx * h.x(), sy * h.y(), -h.z());
      const Vec3d below(corner.x(), corner.y(), plane);
      const double gap = corner.z() - plane;
      out.push_back(boxFirst ? Expected{corner, below, gap} : Expected{below, corner, gap});
    }
  return out;
}

double gBulletError = 0;  // the largest error of Bullet's float distance in these tests

TEST(ConvexContact, BoxOnBoxFaceToFace) {
  // A small box (half 0.5) over the top face of a large one (half 1): its 4 bottom corners at the
  // gap, separated (0.3) and interpenetrating (-0.2), turned about the vertical or not.
  const Vec3d h(0.5, 0.4, 0.5);
  const ConvexPrimitive big = boxAt(Vec3d::Zero(), Vec3d::Ones());
  for (double gap : {0.3, -0.2})
    for (double turn : {0.0, 0.6}) {
      const Vec3d c(0.1, -0.2, 1 + h.z() + gap);
      const Mat3d Rz = rotation(turn, Vec3d::UnitZ());
      gBulletError = std::max(
          gBulletError, expectContacts(big, boxAt(c, h, Rz), 0.5, Vec3d::UnitZ(),
                                       cornersOverPlane(c, h, 1.0, false, Rz), "face on face"));
    }
}

TEST(ConvexContact, BoxesOfEqualFacesOverlapIn8Points) {
  // Two equal squares turned by 45 degrees: their intersection is a regular octagon, whose 8
  // vertices are the contacts (gap 0.1 apart, the reference face the first box's top).
  const double s = 1.0, gap = 0.1;
  const ConvexPrimitive lower = boxAt(Vec3d::Zero(), Vec3d(s, s, 1));
  const ConvexPrimitive upper =
      boxAt(Vec3d(0, 0, 2 + gap), Vec3d(s, s, 1), rotation(std::numbers::pi / 4, Vec3d::UnitZ()));
  std::vector<Expected> octagon;
  const double t = s * (std::sqrt(2.0) - 1);  // where the turned square crosses x = s
  for (double a : {-1.0, 1.0})
    for (double b : {-1.0, 1.0}) {
      octagon.push_back({Vec3d(a * s, b * t, 1), Vec3d(a * s, b * t, 1 + gap), gap});
      octagon.push_back({Vec3d(b * t, a * s, 1), Vec3d(b * t, a * s, 1 + gap), gap});
    }
  gBulletError =
      std::max(gBulletError, expectContacts(lower, upper, 0.5, Vec3d::UnitZ(), octagon, "octagon"));
}

TEST(ConvexContact, BoxEdgeAcrossBoxEdge) {
  // A's top is an edge along x at height sqrt(2) (turned 45 degrees about x), B's bottom an edge
  // along y (turned about y): they cross above the origin, one contact, along z.
  const double r2 = std::sqrt(2.0);
  const ConvexPrimitive a =
      boxAt(Vec3d::Zero(), Vec3d::Ones(), rotation(std::numbers::pi / 4, Vec3d::UnitX()));
  for (double gap : {0.3, -0.1}) {
    const double zc = 2 * r2 + gap;
    const ConvexPrimitive b =
        boxAt(Vec3d(0, 0, zc), Vec3d::Ones(), rotation(std::numbers::pi / 4, Vec3d::UnitY()));
    gBulletError = std::max(
        gBulletError, expectContacts(a, b, 0.5, Vec3d::UnitZ(),
                                     {{Vec3d(0, 0, r2), Vec3d(0, 0, zc - r2), gap}}, "edge-edge"));
  }
}

TEST(ConvexContact, BoxCornerOnBoxFace) {
  // B's corner (0.5, 0.5, 0.5) turned to point straight down, at the gap above A's top face.
  const Mat3d down =
      Eigen::Quaterniond::FromTwoVectors(Vec3d(-1, -1, -1), -Vec3d::UnitZ()).toRotationMatrix();
  const double reach = 0.5 * std::sqrt(3.0);
  for (double gap : {0.2, -0.1}) {
    const Vec3d c(0.3, 0.1, 1 + reach + gap);
    gBulletError = std::max(
        gBulletError, expectContacts(boxAt(Vec3d::Zero(), Vec3d::Ones()),
                                     boxAt(c, Vec3d::Constant(0.5), down), 0.4, Vec3d::UnitZ(),
                                     {{Vec3d(c.x(), c.y(), 1), Vec3d(c.x(), c.y(), 1 + gap), gap}},
                                     "vertex-face"));
  }
}

TEST(ConvexContact, BoxAgainstPoint) {
  // A point (a sphere's centre) over a face, beside an edge, beside a corner, inside.
  const Vec3d h(1, 2, 0.5);
  const ConvexPrimitive b = boxAt(Vec3d::Zero(), h);
  auto point = [](const Vec3d& p) { return ConvexPrimitive::point(p); };
  gBulletError =
      std::max(gBulletError,
               expectContacts(b, point(Vec3d(0.2, 0.3, 0.9)), 1, Vec3d::UnitZ(),
                              {{Vec3d(0.2, 0.3, 0.5), Vec3d(0.2, 0.3, 0.9), 0.4}}, "over a face"));
  const Vec3d edgeDir = Vec3d(0.3, 0, 0.4) / 0.5;
  gBulletError =
      std::max(gBulletError,
               expectContacts(b, point(Vec3d(1.3, 0.7, 0.9)), 1, edgeDir,
                              {{Vec3d(1, 0.7, 0.5), Vec3d(1.3, 0.7, 0.9), 0.5}}, "by an edge"));
  const Vec3d cornerDir = Vec3d(0.2, 0.3, 0.6) / 0.7;
  gBulletError =
      std::max(gBulletError, expectContacts(b, point(Vec3d(1.2, 2.3, 1.1)), 1, cornerDir,
                                            {{h, Vec3d(1.2, 2.3, 1.1), 0.7}}, "by a corner"));
  // Inside, nearest the +x face (0.1 away): pushed out along x.
  gBulletError = std::max(
      gBulletError, expectContacts(b, point(Vec3d(0.9, 0.5, 0.1)), 1, Vec3d::UnitX(),
                                   {{Vec3d(1, 0.5, 0.1), Vec3d(0.9, 0.5, 0.1), -0.1}}, "inside"));
  // Beyond the limit: nothing.
  ConvexContacts c;
  EXPECT_FALSE(computeConvexContacts(b, point(Vec3d(0, 0, 1.6)), 1.0, c));
  EXPECT_TRUE(computeConvexContacts(b, point(Vec3d(0, 0, 1.4)), 1.0, c));
}

TEST(ConvexContact, BoxAgainstSegment) {
  const ConvexPrimitive b = boxAt(Vec3d::Zero(), Vec3d::Ones());
  // Lying over the top face, crossing its border: clipped at x = 1.
  gBulletError = std::max(
      gBulletError,
      expectContacts(b, ConvexPrimitive::segment(Vec3d(0.2, 0.1, 1.3), Vec3d(1.8, 0.1, 1.3)), 0.5,
                     Vec3d::UnitZ(),
                     {{Vec3d(0.2, 0.1, 1), Vec3d(0.2, 0.1, 1.3), 0.3},
                      {Vec3d(1, 0.1, 1), Vec3d(1, 0.1, 1.3), 0.3}},
                     "segment on a face"));
  // Across the edge x = 1, z = 1 (not parallel to it), 0.2 away along the diagonal d: one
  // contact, the closest points of the two lines.
  const Vec3d d = Vec3d(1, 0, 1).normalized();
  const Vec3d p = Vec3d(1, 0, 1) + 0.2 * d, w(0.3, 1, -0.3);
  gBulletError =
      std::max(gBulletError, expectContacts(b, ConvexPrimitive::segment(p - 2 * w, p + 2 * w), 0.5,
                                            d, {{Vec3d(1, 0, 1), p, 0.2}}, "segment over an edge"));
}

TEST(ConvexContact, BoxOnTriangle) {
  // A floor triangle at z = 0 (normal +z, one-sided), large; the box first and second.
  const ConvexPrimitive floor =
      ConvexPrimitive::triangle(Vec3d(-10, -10, 0), Vec3d(10, -10, 0), Vec3d(0, 10, 0), true);
  const Vec3d h(0.5, 0.3, 0.2);
  for (double gap : {0.05, -0.02}) {
    const Vec3d c(0.5, 0.2, h.z() + gap);
    const Mat3d Rz = rotation(0.3, Vec3d::UnitZ());
    gBulletError = std::max(gBulletError,
                            expectContacts(floor, boxAt(c, h, Rz), 0.1, Vec3d::UnitZ(),
                                           cornersOverPlane(c, h, 0, false, Rz), "box on a floor"));
    gBulletError = std::max(
        gBulletError, expectContacts(boxAt(c, h, Rz), floor, 0.1, -Vec3d::UnitZ(),
                                     cornersOverPlane(c, h, 0, true, Rz), "floor under a box"));
  }
  // Tilted about x by a small angle: each corner at its own height; the higher two beyond the
  // limit are left out.
  const Mat3d tilt = rotation(0.2, Vec3d::UnitX());
  const Vec3d c(0.1, 0.2, 0.4);
  std::vector<Expected> low;
  for (int k = 0; k < 8; ++k) {
    const Vec3d corner = c + tilt * Vec3d((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(),
                                          (k & 4) ? h.z() : -h.z());
    if (corner.z() < 0.2) low.push_back({Vec3d(corner.x(), corner.y(), 0), corner, corner.z()});
  }
  ASSERT_EQ(low.size(), 2u);
  gBulletError = std::max(
      gBulletError, expectContacts(floor, boxAt(c, h, tilt), 0.2, Vec3d::UnitZ(), low, "tilted"));
  // Behind the one-sided floor: nothing; a two-sided floor pushes it down.
  ConvexContacts out;
  EXPECT_FALSE(computeConvexContacts(floor, boxAt(Vec3d(0, 0, -0.25), h), 0.1, out));
  const ConvexPrimitive both =
      ConvexPrimitive::triangle(Vec3d(-10, -10, 0), Vec3d(10, -10, 0), Vec3d(0, 10, 0), false);
  EXPECT_TRUE(computeConvexContacts(both, boxAt(Vec3d(0, 0, -0.25), h), 0.1, out));
  EXPECT_LT((out.normal + Vec3d::UnitZ()).norm(), kExact);
  EXPECT_NEAR(out.distance, 0.05, kExact);
}

TEST(ConvexContact, BoxOverATriangleBorderKeepsThePartOverIt) {
  // The floor triangle ends at x = 0 (its edge from (0, -10) to (0, 10)); a box straddling it
  // gets its two corners over the triangle and the two points where its face crosses the edge.
  const ConvexPrimitive floor =
      ConvexPrimitive::triangle(Vec3d(0, -10, 0), Vec3d(10, 0, 0), Vec3d(0, 10, 0), true);
  const Vec3d h(0.5, 0.5, 0.5), c(0.2, 0, 0.6);
  gBulletError =
      std::max(gBulletError, expectContacts(floor, boxAt(c, h), 0.3, Vec3d::UnitZ(),
                                            {{Vec3d(0.7, -0.5, 0), Vec3d(0.7, -0.5, 0.1), 0.1},
                                             {Vec3d(0.7, 0.5, 0), Vec3d(0.7, 0.5, 0.1), 0.1},
                                             {Vec3d(0, -0.5, 0), Vec3d(0, -0.5, 0.1), 0.1},
                                             {Vec3d(0, 0.5, 0), Vec3d(0, 0.5, 0.1), 0.1}},
                                            "straddling"));
}

// The exact distance of two separated boxes by brute force: each corner of one against the other
// (clamped in its frame) and each edge against each edge.
double bruteForceDistance(const OrientedBox& a, const OrientedBox& b) {
  auto corner = [](const OrientedBox& x, int k) {
    Vec3d local;
    for (int i = 0; i < 3; ++i) local[i] = (k >> i & 1) ? x.halfExtents[i] : -x.halfExtents[i];
    return Vec3d(x.center + x.rotation * local);
  };
  auto toBox = [](const Vec3d& p, const OrientedBox& x) {
    const Vec3d local = x.rotation.transpose() * (p - x.center);
    return (local - local.cwiseMax(-x.halfExtents).cwiseMin(x.halfExtents)).norm();
  };
  double d = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 8; ++k) d = std::min({d, toBox(corner(a, k), b), toBox(corner(b, k), a)});
  for (int i = 0; i < 8; ++i)
    for (int ai = 0; ai < 3; ++ai)
      for (int j = 0; j < 8 && !(i >> ai & 1); ++j)
        for (int bi = 0; bi < 3; ++bi)
          if (!(j >> bi & 1))
            d = std::min(d, closestPointsOfSegments(corner(a, i), corner(a, i | 1 << ai),
                                                    corner(b, j), corner(b, j | 1 << bi))
                                .distance);
  return d;
}

TEST(ConvexContact, RandomBoxPairsGiveTheExactDistanceAndDepth) {
  // 20000 random pairs of boxes: when they interpenetrate the distance is minus the overlap
  // along the separating axis of least overlap (the 15 axes of two boxes); when apart it is
  // the brute-force distance. Every contact point lies on its box. Bullet's GJK in float stops
  // early on some separated pairs (its distance then off by up to 0.16): the answer must not
  // depend on it.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1, 1);
  auto randomBox = [&](const Vec3d& center) {
    return box(center, Vec3d(0.5 + 0.4 * u(random), 0.5 + 0.4 * u(random), 0.5 + 0.4 * u(random)),
               rotation(3 * u(random), Vec3d(u(random), u(random), u(random))));
  };
  int penetrating = 0, separated = 0, bulletOff = 0;
  for (int n = 0; n < 20000; ++n) {
    const OrientedBox a = randomBox(Vec3d::Zero());
    const OrientedBox b = randomBox(Vec3d(u(random), u(random), u(random)) * 2);
    auto support = [](const OrientedBox& x, const Vec3d& d) {
      return d.dot(x.center) + (x.rotation.transpose() * d).cwiseAbs().dot(x.halfExtents);
    };
    double sat = -std::numeric_limits<double>::infinity();
    std::vector<Vec3d> axes;
    for (int i = 0; i < 3; ++i) {
      axes.push_back(a.rotation.col(i));
      axes.push_back(b.rotation.col(i));
      for (int j = 0; j < 3; ++j) {
        const Vec3d c = a.rotation.col(i).cross(b.rotation.col(j));
        if (c.norm() > 1e-6) axes.push_back(c.normalized());
      }
    }
    for (const Vec3d& d : axes) {
      sat = std::max(sat, -support(b, -d) - support(a, d));
      sat = std::max(sat, -support(b, d) - support(a, -d));
    }
    ConvexContacts c;
    const ConvexPrimitive pa = ConvexPrimitive::orientedBox(a),
                          pb = ConvexPrimitive::orientedBox(b);
    if (!computeConvexContacts(pa, pb, 10, c)) {
      ADD_FAILURE() << "no contact within 10";
      continue;
    }
    if (sat < 0) {
      ++penetrating;
      EXPECT_NEAR(c.distance, sat, kExact) << n;
    } else {
      ++separated;
      const double exact = bruteForceDistance(a, b);
      EXPECT_NEAR(c.distance, exact, kExact) << n;
      bulletOff += std::abs(computeGjkEpa(pa, pb).distance - exact) > 1e-4;
    }
    auto inBox = [](const OrientedBox& x, const Vec3d& p) {
      return ((x.rotation.transpose() * (p - x.center)).cwiseAbs() - x.halfExtents).maxCoeff();
    };
    for (int k = 0; k < c.count; ++k) {
      EXPECT_LT(std::abs(inBox(a, c.points[k].onFirst)), kExact) << n;
      EXPECT_LT(std::abs(inBox(b, c.points[k].onSecond)), kExact) << n;
    }
  }
  EXPECT_GT(penetrating, 1000);
  EXPECT_GT(separated, 1000);
  EXPECT_GT(bulletOff, 0) << "no pair where GJK stops early: the fallback is untested";
  std::printf("%d penetrating, %d separated pairs; Bullet's distance off by more than 1e-4 on %d\n",
              penetrating, separated, bulletOff);
}

TEST(ConvexContact, RandomBoxTrianglePairsGiveTheExactDistanceAndDepth) {
  // The same for a box against a two-sided triangle: the brute-force distance (corners against
  // the triangle, vertices against the box, edges against edges) when apart, the least overlap
  // along the 13 separating axes (3 box faces, the triangle's normal, 9 edge pairs) when not.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int penetrating = 0, separated = 0;
  for (int n = 0; n < 10000; ++n) {
    const OrientedBox b = box(
        Vec3d::Zero(), Vec3d(0.5 + 0.4 * u(random), 0.5 + 0.4 * u(random), 0.5 + 0.4 * u(random)),
        rotation(3 * u(random), Vec3d(u(random), u(random), u(random))));
    const Vec3d centre = 1.5 * Vec3d(u(random), u(random), u(random));
    std::array<Vec3d, 3> t;
    for (Vec3d& v : t) v = centre + Vec3d(u(random), u(random), u(random));
    const ConvexPrimitive pb = ConvexPrimitive::orientedBox(b);
    const ConvexPrimitive pt = ConvexPrimitive::triangle(t[0], t[1], t[2], false);
    std::vector<Vec3d> axes = {b.rotation.col(0), b.rotation.col(1), b.rotation.col(2),
                               (t[1] - t[0]).cross(t[2] - t[0]).normalized()};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        const Vec3d c = b.rotation.col(i).cross(t[(k + 1) % 3] - t[k]);
        if (c.norm() > 1e-6) axes.push_back(c.normalized());
      }
    double sat = -std::numeric_limits<double>::infinity();
    for (const Vec3d& d : axes)
      for (double sign : {1.0, -1.0}) {
        const Vec3d e = sign * d;
        double lo = std::numeric_limits<double>::infinity();
        for (const Vec3d& v : t) lo = std::min(lo, e.dot(v));
        sat = std::max(
            sat, lo - e.dot(b.center) - (b.rotation.transpose() * e).cwiseAbs().dot(b.halfExtents));
      }
    ConvexContacts c;
    if (!computeConvexContacts(pb, pt, 10, c)) {
      ADD_FAILURE() << "no contact within 10";
      continue;
    }
    if (sat < 0) {
      ++penetrating;
      EXPECT_NEAR(c.distance, sat, kExact) << n;
      continue;
    }
    ++separated;
    auto corner = [&](int k) {
      Vec3d local;
      for (int i = 0; i < 3; ++i) local[i] = (k >> i & 1) ? b.halfExtents[i] : -b.halfExtents[i];
      return Vec3d(b.center + b.rotation * local);
    };
    double exact = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 8; ++k)
      exact = std::min(exact, closestPointOnTriangle(corner(k), t[0], t[1], t[2]).distance);
    for (const Vec3d& v : t) {
      const Vec3d local = b.rotation.transpose() * (v - b.center);
      exact =
          std::min(exact, (local - local.cwiseMax(-b.halfExtents).cwiseMin(b.halfExtents)).norm());
    }
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i)
        if (!(k >> i & 1))
          for (int e = 0; e < 3; ++e)
            exact = std::min(
                exact, closestPointsOfSegments(corner(k), corner(k | 1 << i), t[e], t[(e + 1) % 3])
                           .distance);
    EXPECT_NEAR(c.distance, exact, kExact) << n;
  }
  EXPECT_GT(penetrating, 1000);
  EXPECT_GT(separated, 1000);
}

TEST(ConvexContact, RandomBoxSegmentAndBoxPointPairsGiveTheExactDistanceAndDepth) {
  // A segment: the brute-force distance (its ends against the box, the box's corners against it,
  // edges against it) when apart, the least overlap along the 6 separating axes (3 box faces,
  // 3 box edges across the segment) when it crosses the box. A point: its distance to the box,
  // or minus its depth under the nearest face.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int crossing = 0, inside = 0;
  for (int n = 0; n < 20000; ++n) {
    const OrientedBox b = box(
        Vec3d::Zero(), Vec3d(0.5 + 0.4 * u(random), 0.5 + 0.4 * u(random), 0.5 + 0.4 * u(random)),
        rotation(3 * u(random), Vec3d(u(random), u(random), u(random))));
    auto corner = [&](int k) {
      Vec3d local;
      for (int i = 0; i < 3; ++i) local[i] = (k >> i & 1) ? b.halfExtents[i] : -b.halfExtents[i];
      return Vec3d(b.center + b.rotation * local);
    };
    auto signedToBox = [&](const Vec3d& p) {
      const Vec3d local = b.rotation.transpose() * (p - b.center);
      const double out = (local - local.cwiseMax(-b.halfExtents).cwiseMin(b.halfExtents)).norm();
      return out > 0 ? out : -(b.halfExtents - local.cwiseAbs()).minCoeff();
    };
    const Vec3d p0 = 1.5 * Vec3d(u(random), u(random), u(random));
    const Vec3d p1 = p0 + Vec3d(u(random), u(random), u(random));
    double exact = std::min(signedToBox(p0), signedToBox(p1));
    for (int k = 0; k < 8; ++k) {
      exact = std::min(exact, closestPointOnSegment(corner(k), p0, p1).distance);
      for (int i = 0; i < 3; ++i)
        if (!(k >> i & 1))
          exact = std::min(exact,
                           closestPointsOfSegments(corner(k), corner(k | 1 << i), p0, p1).distance);
    }
    double sat = -std::numeric_limits<double>::infinity();
    std::vector<Vec3d> axes = {b.rotation.col(0), b.rotation.col(1), b.rotation.col(2)};
    for (int i = 0; i < 3; ++i) {
      const Vec3d c = b.rotation.col(i).cross(p1 - p0);
      if (c.norm() > 1e-9) axes.push_back(c.normalized());
    }
    for (const Vec3d& d : axes)
      for (double sign : {1.0, -1.0}) {
        const Vec3d e = sign * d;
        sat = std::max(sat, std::min(e.dot(p0), e.dot(p1)) - e.dot(b.center) -
                                (b.rotation.transpose() * e).cwiseAbs().dot(b.halfExtents));
      }
    crossing += sat < 0;
    ConvexContacts c;
    ASSERT_TRUE(computeConvexContacts(ConvexPrimitive::orientedBox(b),
                                      ConvexPrimitive::segment(p0, p1), 10, c))
        << n;
    EXPECT_NEAR(c.distance, sat < 0 ? sat : exact, kExact) << n;
    const double point = signedToBox(p0);
    inside += point < 0;
    ASSERT_TRUE(
        computeConvexContacts(ConvexPrimitive::orientedBox(b), ConvexPrimitive::point(p0), 10, c))
        << n;
    EXPECT_NEAR(c.distance, point, kExact) << n;
  }
  EXPECT_GT(crossing, 1000);
  EXPECT_GT(inside, 500);
}

TEST(ConvexContact, RandomBoxesOverALargeFloorTriangle) {
  // 20 cm boxes, turned by up to 0.3 rad, around a floor triangle 20 m across (two orders of
  // magnitude apart: Bullet's absolute tolerances must not be those of the floor): the distance
  // is the height of the lowest corner, negative below the floor, and every corner within the
  // limit whose face is the one turned to the floor is a contact at its own height.
  const ConvexPrimitive floor =
      ConvexPrimitive::triangle(Vec3d(-10, -10, 0), Vec3d(10, -10, 0), Vec3d(0, 10, 0), true);
  std::mt19937 random(13);
  std::uniform_real_distribution<double> u(-1, 1);
  const double limit = 0.05;
  for (int n = 0; n < 20000; ++n) {
    const OrientedBox b =
        box(Vec3d(u(random), u(random), 0.1 + 0.05 * u(random)), Vec3d::Constant(0.1),
            rotation(0.3 * u(random), Vec3d(u(random), u(random), u(random))));
    double lowest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 8; ++k) {
      Vec3d local;
      for (int i = 0; i < 3; ++i) local[i] = (k >> i & 1) ? 0.1 : -0.1;
      lowest = std::min(lowest, (b.center + b.rotation * local).z());
    }
    ConvexContacts c;
    const bool found = computeConvexContacts(floor, ConvexPrimitive::orientedBox(b), limit, c);
    ASSERT_EQ(found, lowest < limit) << n;
    if (!found) continue;
    EXPECT_NEAR(c.distance, lowest, kExact) << n;
    EXPECT_LT((c.normal - Vec3d::UnitZ()).norm(), kExact) << n;
    for (int k = 0; k < c.count; ++k) {
      EXPECT_NEAR(c.points[k].onFirst.z(), 0, kExact) << n;
      EXPECT_NEAR(c.points[k].onSecond.z(), c.points[k].distance, kExact) << n;
      EXPECT_LT(c.points[k].distance, limit) << n;
    }
  }
}

TEST(ConvexContact, BulletsOwnDistanceIsFloatAccurate) {
  // Measured over the configurations above (run after them): Bullet's single-precision answer
  // differs from the exact one by this much; the refinement removes it.
  std::printf("largest error of Bullet's GJK/EPA distance over these configurations: %.3g\n",
              gBulletError);
  EXPECT_LT(gBulletError, 1e-3);
}

}  // namespace
}  // namespace stroma::collision
