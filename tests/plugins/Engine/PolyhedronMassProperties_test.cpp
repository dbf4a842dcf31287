// SPDX-License-Identifier: MIT
// The mass-property kernel of GenerateRigidMass (plugins/Engine/src/PolyhedronMassProperties):
// closed forms for boxes, the rotated inertia R I R^T of a moved box, exactness on an arbitrary
// closed surface against an independent formula, convergence to the solid sphere, and the
// closedness check.
#include "../../../plugins/Engine/src/PolyhedronMassProperties.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "SurfaceMeshes.h"

namespace stroma::test {
namespace {

PolyhedronMassProperties compute(const Surface& s) {
  return computePolyhedronMassProperties(s.points, s.triangles, s.quads);
}

/// The box [0, a] x [0, b] x [0, c] of unit density: V = abc, c = (a, b, c) / 2,
/// I = V / 12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2).
Mat3d boxInertia(double a, double b, double c) {
  return a * b * c / 12 * Vec3d(b * b + c * c, a * a + c * c, a * a + b * b).asDiagonal();
}

/// Independent reference: the solid as signed tetrahedra (0, p0, p1, p2) over the faces, each
/// with volume det / 6, first moment V (p0 + p1 + p2) / 4 and second moment
/// V / 20 (sum p p^T + s s^T), s = p0 + p1 + p2 (F. Tonon, "Explicit exact formulas for the 3-D
/// tetrahedron inertia tensor in terms of its vertex coordinates", J. Math. Stat. 1(1), 2004).
PolyhedronMassProperties signedTetrahedra(const Surface& s) {
  double V = 0;
  Vec3d first = Vec3d::Zero();
  Mat3d second = Mat3d::Zero();
  for (const Triangle& f : s.triangles) {
    const Vec3d &a = s.points[f[0]], &b = s.points[f[1]], &c = s.points[f[2]];
    const double v = a.dot(b.cross(c)) / 6;
    const Vec3d sum = a + b + c;
    V += v;
    first += v * sum / 4;
    second += v / 20 *
              (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  PolyhedronMassProperties p;
  p.volume = V;
  p.center = first / V;
  const Mat3d C = second - V * p.center * p.center.transpose();
  p.inertia = C.trace() * Mat3d::Identity() - C;
  return p;
}

double relative(const Mat3d& got, const Mat3d& expected) {
  return (got - expected).norm() / expected.norm();
}

TEST(PolyhedronMassProperties, UnitCube) {
  const PolyhedronMassProperties p = compute(boxSurface(1, 1, 1));
  EXPECT_NEAR(p.volume, 1, 1e-15);
  EXPECT_LT((p.center - Vec3d(0.5, 0.5, 0.5)).norm(), 1e-15);
  EXPECT_LT((p.inertia - Mat3d::Identity() / 6).norm(), 1e-15) << p.inertia;
}

TEST(PolyhedronMassProperties, BoxOfTrianglesOrQuads) {
  const double a = 0.3, b = 1.7, c = 2.9;
  for (bool asQuads : {false, true}) {
    SCOPED_TRACE(asQuads ? "quads" : "triangles");
    const PolyhedronMassProperties p = compute(boxSurface(a, b, c, asQuads));
    EXPECT_NEAR(p.volume, a * b * c, 1e-15 * a * b * c);
    EXPECT_LT((p.center - Vec3d(a, b, c) / 2).norm(), 1e-15);
    EXPECT_LT(relative(p.inertia, boxInertia(a, b, c)), 1e-15) << p.inertia;
  }
}

TEST(PolyhedronMassProperties, MovedBoxHasTheRotatedInertiaAboutItsCenter) {
  // The box turned by R and moved 2300 units from the origin: the center goes to R c + t, the
  // inertia about it is R I R^T. Measured: volume and inertia within 1.7e-13 and 1.3e-13
  // relative, the rounding of the moved points (ulp 2.3e-13 at 2000, for a box of 0.3).
  // Integrating about the world origin instead gave 2.8e-6 on the inertia (and 3e+3 at 10^6
  // units): the c^2 terms of the second moments cancel.
  const double a = 0.3, b = 1.7, c = 2.9;
  const Mat3d R = Eigen::AngleAxisd(0.7, Vec3d(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3d t(1000, -2000, 500);
  Surface s = boxSurface(a, b, c);
  for (Vec3d& p : s.points) p = R * p + t;
  const PolyhedronMassProperties p = compute(s);
  EXPECT_NEAR(p.volume, a * b * c, 1e-12 * a * b * c);
  EXPECT_LT((p.center - (R * Vec3d(a, b, c) / 2 + t)).norm(), 1e-12);
  const Mat3d expected = R * boxInertia(a, b, c) * R.transpose();
  EXPECT_LT(relative(p.inertia, expected), 1e-12) << p.inertia << "\nexpected\n" << expected;
  EXPECT_GT(std::abs(expected(0, 1)), 0.01 * expected.norm());  // off-diagonal terms checked
}

TEST(PolyhedronMassProperties, ExactOnAnArbitraryClosedSurface) {
  // A lumpy geodesic sphere (random radius per point), turned and moved: the same numbers as the
  // signed-tetrahedra decomposition, a different formula.
  Surface s = icosphere(2, 1.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> radius(0.5, 1.5);
  const Mat3d R = Eigen::AngleAxisd(1.1, Vec3d(-1, 0.5, 2).normalized()).toRotationMatrix();
  for (Vec3d& p : s.points) p = R * (radius(random) * p) + Vec3d(3, -1, 2);
  const PolyhedronMassProperties p = compute(s), reference = signedTetrahedra(s);
  EXPECT_NEAR(p.volume, reference.volume, 1e-13 * reference.volume);
  EXPECT_LT((p.center - reference.center).norm(), 1e-13);
  EXPECT_LT(relative(p.inertia, reference.inertia), 1e-12);
}

TEST(PolyhedronMassProperties, SphereConvergesToTwoFifthsMassRadiusSquared) {
  // Inscribed geodesic spheres: V -> 4/3 pi r^3 and I -> 2/5 m r^2 Id, the error falling by 4
  // per level (second order in the edge length h, which halves per level). Measured relative
  // errors of I / (2/5 m r^2) (Frobenius): 2.26e-2 (level 2, 320 triangles), 5.74e-3, 1.44e-3,
  // 3.61e-4 (level 5, 20480 triangles), ratios 3.94, 3.99, 3.99; of V: 3.38e-2 ... 5.41e-4.
  const double r = 0.7;
  double previous = 0;
  for (int level = 2; level <= 5; ++level) {
    const PolyhedronMassProperties p = compute(icosphere(level, r));
    const double volumeError = 1 - p.volume / (4.0 / 3 * std::numbers::pi * r * r * r);
    const Mat3d perUnitMass = p.inertia / p.volume;
    const double inertiaError =
        (perUnitMass - 0.4 * r * r * Mat3d::Identity()).norm() / (0.4 * r * r * std::sqrt(3.0));
    SCOPED_TRACE("level " + std::to_string(level) + ": volume error " +
                 std::to_string(volumeError) + ", inertia error " + std::to_string(inertiaError));
    EXPECT_GT(volumeError, 0);  // inscribed: smaller
    EXPECT_LT(p.center.norm(), 1e-14);
    if (level > 2) {
      EXPECT_NEAR(previous / inertiaError, 4, 0.2);
    }
    if (level == 5) {
      EXPECT_LT(inertiaError, 4e-4);
      EXPECT_LT(volumeError, 6e-4);
    }
    previous = inertiaError;
  }
}

TEST(PolyhedronMassProperties, ReversedFacesNegateVolumeAndInertia) {
  Surface s = boxSurface(1, 2, 3);
  for (Triangle& f : s.triangles) std::swap(f[1], f[2]);
  const PolyhedronMassProperties p = compute(s);
  EXPECT_NEAR(p.volume, -6, 1e-14);
  EXPECT_LT((p.center - Vec3d(0.5, 1, 1.5)).norm(), 1e-15);
  EXPECT_LT(relative(-p.inertia, boxInertia(1, 2, 3)), 1e-15);
}

TEST(PolyhedronMassProperties, UnmatchedEdges) {
  const Surface closed = boxSurface(1, 1, 1);
  EXPECT_FALSE(findUnmatchedEdge(closed.points, closed.triangles, closed.quads));
  EXPECT_FALSE(findUnmatchedEdge(closed.points, {}, boxSurface(1, 1, 1, true).quads));

  // A hole: the last triangle (1 7 5) removed; its edges are now run one way only.
  Surface open = closed;
  open.triangles.pop_back();
  const auto hole = findUnmatchedEdge(open.points, open.triangles, {});
  ASSERT_TRUE(hole);
  EXPECT_FALSE(hole->inQuad);
  const Triangle& face = open.triangles[hole->face];
  bool runsIt = false;
  for (int k = 0; k < 3; ++k) runsIt |= face[k] == hole->from && face[(k + 1) % 3] == hole->to;
  EXPECT_TRUE(runsIt) << "edge " << hole->from << " " << hole->to << " not in face " << hole->face;

  // One face flipped: its edges run the same way as their neighbours'.
  Surface flipped = closed;
  std::swap(flipped.triangles[4][1], flipped.triangles[4][2]);
  EXPECT_TRUE(findUnmatchedEdge(flipped.points, flipped.triangles, {}));

  // Points duplicated along a seam (as an OBJ file with texture coordinates is read): still
  // closed. The top face's corners get their own copies.
  Surface seams = closed;
  for (Triangle& f : seams.triangles)
    if (seams.points[f[0]].z() == 1 && seams.points[f[1]].z() == 1 && seams.points[f[2]].z() == 1)
      for (Index& i : f) {
        seams.points.push_back(seams.points[i]);
        i = static_cast<Index>(seams.points.size() - 1);
      }
  EXPECT_EQ(seams.points.size(), 8u + 6);
  EXPECT_FALSE(findUnmatchedEdge(seams.points, seams.triangles, {}));
  EXPECT_NEAR(compute(seams).volume, 1, 1e-15);

  // Two cubes sharing an edge (non-manifold, balanced): closed, volume 2.
  Surface two = closed;
  for (const Triangle& f : boxSurface(1, 1, 1).triangles) {
    Triangle g = f;
    for (Index& i : g) i += 8;
    two.triangles.push_back(g);
  }
  for (const Vec3d& p : closed.points) two.points.push_back(p + Vec3d(1, 1, 0));
  EXPECT_FALSE(findUnmatchedEdge(two.points, two.triangles, {}));
  EXPECT_NEAR(compute(two).volume, 2, 1e-15);
}

}  // namespace
}  // namespace stroma::test
