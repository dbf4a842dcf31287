// SPDX-License-Identifier: MIT
#include "topology/MeshGeometry.h"

#include <gtest/gtest.h>

#include "framework/topology/CubeMeshes.h"

namespace stroma::test {
namespace {

TEST(MeshGeometry, SignedVolumeFollowsSofaVertexOrder) {
  const Vec3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1);
  EXPECT_DOUBLE_EQ(signedTetrahedronVolume(a, b, c, d), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(signedTetrahedronVolume(a, c, b, d), -1.0 / 6.0);
}

TEST(MeshGeometry, CubeSplitsSumToTheCubeVolume) {
  const auto p = unitCubePoints();
  double five = 0, six = 0;
  for (const auto& t : cubeInFiveTetrahedra()) five += signedVolume(p, t);
  for (const auto& t : cubeInSixTetrahedra()) six += signedVolume(p, t);
  EXPECT_NEAR(five, 1.0, 1e-14);
  EXPECT_NEAR(six, 1.0, 1e-14);
  EXPECT_NEAR(signedVolume(p, Hexahedron{0, 1, 2, 3, 4, 5, 6, 7}), 1.0, 1e-14);
}

TEST(MeshGeometry, TetrahedronQuality) {
  const std::vector<Vec3d> p{Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1),
                             Vec3d(0.5, 0.5, 0)};
  EXPECT_EQ(tetrahedronQuality(p, {0, 1, 2, 3}), ElementQuality::good);
  EXPECT_EQ(tetrahedronQuality(p, {0, 2, 1, 3}), ElementQuality::inverted);
  EXPECT_EQ(tetrahedronQuality(p, {0, 1, 2, 4}), ElementQuality::degenerate);  // flat
  EXPECT_EQ(tetrahedronQuality(p, {0, 0, 2, 3}), ElementQuality::degenerate);  // repeated vertex
  // Scale does not change the class.
  std::vector<Vec3d> tiny = p;
  for (Vec3d& x : tiny) x *= 1e-6;
  EXPECT_EQ(tetrahedronQuality(tiny, {0, 1, 2, 3}), ElementQuality::good);
}

TEST(MeshGeometry, HexahedronQuality) {
  auto p = unitCubePoints();
  EXPECT_EQ(hexahedronQuality(p, {0, 1, 2, 3, 4, 5, 6, 7}), ElementQuality::good);
  EXPECT_EQ(hexahedronQuality(p, {4, 5, 6, 7, 0, 1, 2, 3}),
            ElementQuality::inverted);  // upside down
  EXPECT_EQ(hexahedronQuality(p, {0, 1, 2, 3, 0, 1, 2, 3}), ElementQuality::degenerate);
  p[6] = Vec3d(1, 1, 0);  // a collapsed corner: zero Jacobian there
  EXPECT_EQ(hexahedronQuality(p, {0, 1, 2, 3, 4, 5, 6, 7}), ElementQuality::degenerate);
}

TEST(MeshGeometry, CheckReportsElementIndicesAndSkipsOutOfRange) {
  const auto p = unitCubePoints();
  const std::vector<Tetrahedron> tets{{0, 1, 3, 4}, {0, 3, 1, 4}, {0, 1, 2, 3}, {0, 1, 3, 99}};
  const QualityReport report = checkTetrahedra(p, tets);
  EXPECT_EQ(report.inverted, (std::vector<Index>{1}));
  EXPECT_EQ(report.degenerate, (std::vector<Index>{2}));
  EXPECT_EQ(findIndicesOutOfRange(std::span<const Tetrahedron>(tets), p.size()),
            (std::vector<Index>{3}));
}

}  // namespace
}  // namespace stroma::test
