// SPDX-License-Identifier: MIT
// The tool-tetrahedron intersection tests of the Cutting plugin against sampled ground truth.
#include "../../../plugins/Cutting/src/CuttingGeometry.h"

#include <gtest/gtest.h>

#include <random>

namespace stroma::cutting {
namespace {

const TetrahedronPoints kTet{Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)};

TEST(CuttingGeometry, PointsAndSegments) {
  EXPECT_TRUE(pointInTetrahedron(Vec3d(0.1, 0.1, 0.1), kTet));
  EXPECT_TRUE(pointInTetrahedron(Vec3d(0, 0, 0), kTet));
  EXPECT_FALSE(pointInTetrahedron(Vec3d(0.5, 0.5, 0.5), kTet));
  // Through the tetrahedron, ends outside.
  EXPECT_TRUE(segmentMeetsTetrahedron(Vec3d(0.2, 0.2, -1), Vec3d(0.2, 0.2, 2), kTet));
  // Beside it.
  EXPECT_FALSE(segmentMeetsTetrahedron(Vec3d(0.6, 0.6, -1), Vec3d(0.6, 0.6, 2), kTet));
  // Stops short of it.
  EXPECT_FALSE(segmentMeetsTetrahedron(Vec3d(0.2, 0.2, -1), Vec3d(0.2, 0.2, -0.1), kTet));
  // Inside entirely.
  EXPECT_TRUE(segmentMeetsTetrahedron(Vec3d(0.1, 0.1, 0.1), Vec3d(0.2, 0.1, 0.1), kTet));
}

TEST(CuttingGeometry, TrianglesAgreeWithSampling) {
  // A big triangle slicing the tetrahedron without any of its edges entering it: only the
  // tetrahedron's edges cross it.
  EXPECT_TRUE(
      triangleMeetsTetrahedron(Vec3d(-5, -5, 0.3), Vec3d(5, -5, 0.3), Vec3d(0, 5, 0.3), kTet));
  EXPECT_FALSE(
      triangleMeetsTetrahedron(Vec3d(-5, -5, 1.3), Vec3d(5, -5, 1.3), Vec3d(0, 5, 1.3), kTet));
  // Random small triangles: when a sample of the triangle lies in the tetrahedron, the test
  // must say they meet.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-0.5, 1.2);
  int met = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3d a(coordinate(random), coordinate(random), coordinate(random));
    const Vec3d b = a + 0.4 * Vec3d(coordinate(random), coordinate(random), coordinate(random));
    const Vec3d c = a + 0.4 * Vec3d(coordinate(random), coordinate(random), coordinate(random));
    bool sampleInside = false;
    for (int i = 0; i <= 20 && !sampleInside; ++i)
      for (int j = 0; i + j <= 20 && !sampleInside; ++j)
        sampleInside = pointInTetrahedron(a + (i / 20.0) * (b - a) + (j / 20.0) * (c - a), kTet);
    const bool meets = triangleMeetsTetrahedron(a, b, c, kTet);
    if (sampleInside) {
      EXPECT_TRUE(meets) << "trial " << trial;
    }
    met += meets;
  }
  EXPECT_GT(met, 100);
}

}  // namespace
}  // namespace stroma::cutting
