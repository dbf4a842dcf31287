// SPDX-License-Identifier: MIT
// The kernel of BarycentricMapping alone: weights in tetrahedra and hexahedra reproduce linear
// fields, lie in [0, 1] and sum to 1 inside; points are found in their element, or the nearest
// one when outside; degenerate elements are reported.
#include "../../../plugins/Mapping/src/BarycentricCoordinates.h"

#include <gtest/gtest.h>

#include <random>

namespace stroma::barycentric {
namespace {

std::mt19937 rng(42);
double uniform(double a = 0, double b = 1) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}
Vec3d randomVec(double a = -1, double b = 1) {
  return Vec3d(uniform(a, b), uniform(a, b), uniform(a, b));
}

// A linear field f(x) = A x + b.
struct LinearField {
  Mat3d A = Mat3d::Random();
  Vec3d b = Vec3d::Random();
  Vec3d operator()(const Vec3d& x) const { return A * x + b; }
};

TEST(BarycentricCoordinates, TetrahedronWeightsRecoverAConvexCombination) {
  for (int trial = 0; trial < 100; ++trial) {
    const std::array<Vec3d, 4> x{randomVec(), randomVec(), randomVec(), randomVec()};
    std::array<double, 4> c{uniform(), uniform(), uniform(), uniform()};
    const double sum = c[0] + c[1] + c[2] + c[3];
    Vec3d p = Vec3d::Zero();
    for (int i = 0; i < 4; ++i) p += (c[i] /= sum) * x[i];
    std::array<double, 4> w;
    ASSERT_TRUE(tetrahedronWeights(x, p, w));
    double total = 0;
    for (int i = 0; i < 4; ++i) {
      // Random tetrahedra can be thin: the error grows with their condition number.
      EXPECT_NEAR(w[i], c[i], 1e-9) << trial;
      EXPECT_GE(w[i], -1e-9);
      EXPECT_LE(w[i], 1 + 1e-9);
      total += w[i];
    }
    EXPECT_NEAR(total, 1.0, 1e-14);
  }
}

TEST(BarycentricCoordinates, TetrahedronWeightsReproduceALinearFieldAnywhere) {
  const LinearField f;
  const std::array<Vec3d, 4> x{Vec3d(0, 0, 0), Vec3d(2, 0, 0), Vec3d(0.3, 1.5, 0),
                               Vec3d(0.5, 0.4, 1.2)};
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3d p = randomVec(-2, 3);  // inside or out: the interpolation is exact either way
    std::array<double, 4> w;
    ASSERT_TRUE(tetrahedronWeights(x, p, w));
    Vec3d interpolated = Vec3d::Zero();
    for (int i = 0; i < 4; ++i) interpolated += w[i] * f(x[i]);
    EXPECT_LT((interpolated - f(p)).norm(), 1e-13 * (1 + f(p).norm()));
  }
}

// Hexahedron of the unit cube moved by x -> M x + t (a parallelepiped), and a distorted one.
std::array<Vec3d, 8> cube(const Mat3d& M = Mat3d::Identity(), const Vec3d& t = Vec3d::Zero()) {
  const std::array<Vec3d, 8> unit{Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 1, 0), Vec3d(0, 1, 0),
                                  Vec3d(0, 0, 1), Vec3d(1, 0, 1), Vec3d(1, 1, 1), Vec3d(0, 1, 1)};
  std::array<Vec3d, 8> x;
  for (int i = 0; i < 8; ++i) x[i] = M * unit[i] + t;
  return x;
}

TEST(BarycentricCoordinates, HexahedronCoordinatesOfABoxAreItsAffineCoordinates) {
  const Vec3d size(2, 0.5, 3), origin(1, -1, 4);
  const auto x = cube(size.asDiagonal(), origin);
  const Vec3d p = origin + Vec3d(0.25, 0.1, 2.4);
  Vec3d uvw;
  ASSERT_TRUE(hexahedronCoordinates(x, p, uvw));
  EXPECT_TRUE(uvw.isApprox(Vec3d(0.125, 0.2, 0.8), 1e-15)) << uvw.transpose();
  const auto w = hexahedronWeights(uvw);
  double total = 0;
  for (double wi : w) {
    total += wi;
    EXPECT_GE(wi, 0.0);
    EXPECT_LE(wi, 1.0);
  }
  EXPECT_NEAR(total, 1.0, 1e-15);
  EXPECT_NEAR(w[6], 0.125 * 0.2 * 0.8, 1e-16);  // vertex (1,1,1)
}

TEST(BarycentricCoordinates, DistortedHexahedronReproducesALinearField) {
  auto x = cube(Mat3d::Identity() + 0.2 * Mat3d::Random(), Vec3d(0.5, 0, -1));
  x[6] += Vec3d(0.15, -0.1, 0.2);  // no longer a parallelepiped: trilinear, not affine
  x[1] += Vec3d(0.05, 0.1, -0.05);
  const LinearField f;
  for (int trial = 0; trial < 50; ++trial) {
    // A point of the element, from local coordinates inside it.
    const Vec3d local(uniform(), uniform(), uniform());
    Vec3d p = Vec3d::Zero();
    const auto n = hexahedronWeights(local);
    for (int i = 0; i < 8; ++i) p += n[i] * x[i];
    Vec3d uvw;
    ASSERT_TRUE(hexahedronCoordinates(x, p, uvw)) << trial;
    EXPECT_LT((uvw - local).norm(), 1e-12) << trial;
    const auto w = hexahedronWeights(uvw);
    Vec3d interpolated = Vec3d::Zero();
    double total = 0;
    for (int i = 0; i < 8; ++i) {
      interpolated += w[i] * f(x[i]);
      total += w[i];
    }
    EXPECT_LT((interpolated - f(p)).norm(), 1e-12 * (1 + f(p).norm()));
    EXPECT_NEAR(total, 1.0, 1e-14);
  }
}

TEST(BarycentricCoordinates, DegenerateElementsAreRefused) {
  std::array<double, 4> w;
  EXPECT_FALSE(tetrahedronWeights({Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(1, 1, 0)},
                                  Vec3d(0.2, 0.2, 0), w));
  Vec3d uvw;
  auto flat = cube(Vec3d(1, 1, 0).asDiagonal());
  EXPECT_FALSE(hexahedronCoordinates(flat, Vec3d(0.5, 0.5, 0), uvw));
}

// The unit cube cut into 6 tetrahedra around its diagonal 0-6, and a second cube as a
// hexahedron beside it (x in [1, 2]).
struct Mesh {
  std::vector<Vec3d> nodes;
  std::vector<Tetrahedron> tetrahedra;
  std::vector<Hexahedron> hexahedra;
  Mesh() {
    for (const Vec3d& c : cube()) nodes.push_back(c);
    for (const Vec3d& c : cube(Mat3d::Identity(), Vec3d(1, 0, 0))) nodes.push_back(c);
    tetrahedra = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                  {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
    hexahedra = {{8, 9, 10, 11, 12, 13, 14, 15}};
  }
};

TEST(EmbedPoints, FindsTheElementContainingEachPoint) {
  const Mesh mesh;
  std::vector<Vec3d> points;
  for (int k = 0; k < 200; ++k) points.push_back(Vec3d(uniform(0, 2), uniform(), uniform()));
  std::vector<Index> degenerate;
  const auto embedded =
      embedPoints(mesh.nodes, mesh.tetrahedra, mesh.hexahedra, points, &degenerate);
  EXPECT_TRUE(degenerate.empty());
  ASSERT_EQ(embedded.size(), points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const EmbeddedPoint& e = embedded[k];
    EXPECT_EQ(e.distance, 0.0) << k;
    EXPECT_EQ(e.count, points[k].x() < 1 ? 4 : 8) << k;
    Vec3d x = Vec3d::Zero();
    double total = 0;
    for (int i = 0; i < e.count; ++i) {
      EXPECT_GE(e.weights[i], -1e-10);
      EXPECT_LE(e.weights[i], 1 + 1e-10);
      x += e.weights[i] * mesh.nodes[e.nodes[i]];
      total += e.weights[i];
    }
    EXPECT_NEAR(total, 1.0, 1e-14);
    EXPECT_LT((x - points[k]).norm(), 1e-14) << k;
  }
}

TEST(EmbedPoints, APointOutsideFollowsTheNearestElement) {
  const Mesh mesh;
  // Beyond the hexahedron's far face, below the tetrahedra, and far away diagonally.
  const std::vector<Vec3d> points{Vec3d(2.5, 0.5, 0.5), Vec3d(0.5, 0.25, -0.2), Vec3d(-3, -3, -3)};
  const auto embedded = embedPoints(mesh.nodes, mesh.tetrahedra, mesh.hexahedra, points);
  EXPECT_EQ(embedded[0].element, 6u);  // the hexahedron, after the 6 tetrahedra
  EXPECT_NEAR(embedded[0].distance, 0.5, 1e-14);
  EXPECT_LT(embedded[1].element, 6u);
  EXPECT_NEAR(embedded[1].distance, 0.2, 1e-14);
  EXPECT_NEAR(embedded[2].distance, std::sqrt(27.0), 1e-12);
  // The weights extrapolate: the point is still reproduced.
  for (std::size_t k = 0; k < points.size(); ++k) {
    Vec3d x = Vec3d::Zero();
    for (int i = 0; i < embedded[k].count; ++i)
      x += embedded[k].weights[i] * mesh.nodes[embedded[k].nodes[i]];
    EXPECT_LT((x - points[k]).norm(), 1e-12) << k;
  }
}

}  // namespace
}  // namespace stroma::barycentric
