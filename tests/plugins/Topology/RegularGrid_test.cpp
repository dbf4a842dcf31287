// SPDX-License-Identifier: MIT
#include "RegularGrid.h"

#include <gtest/gtest.h>

#include <set>

#include "topology/MeshAdjacency.h"
#include "topology/MeshGeometry.h"

namespace stroma::test {
namespace {

TEST(RegularGrid, NumberingIsXFastest) {
  const GridSize n{4, 3, 2};
  EXPECT_EQ(n.points(), 24u);
  EXPECT_EQ(n.point(1, 0, 0), 1u);
  EXPECT_EQ(n.point(0, 1, 0), 4u);
  EXPECT_EQ(n.point(0, 0, 1), 12u);
  const auto points = makeGridPoints(n, Vec3d(1, 2, 3), Vec3d(0.5, 1, 2));
  ASSERT_EQ(points.size(), 24u);
  EXPECT_EQ(points[n.point(3, 2, 1)], Vec3d(2.5, 4, 5));
}

TEST(RegularGrid, HexahedraInSofaOrderArePositive) {
  const GridSize n{4, 3, 2};
  const auto hexahedra = makeGridHexahedra(n);
  ASSERT_EQ(hexahedra.size(), 3u * 2u * 1u);
  EXPECT_EQ(hexahedra[0], (Hexahedron{0, 1, 5, 4, 12, 13, 17, 16}));
  EXPECT_EQ(hexahedra[4], (Hexahedron{5, 6, 10, 9, 17, 18, 22, 21}));  // (i, j) = (1, 1)
  const auto points = makeGridPoints(n, Vec3d::Zero(), Vec3d(1, 1, 1));
  EXPECT_TRUE(checkHexahedra(points, hexahedra).empty());
  double volume = 0;
  for (const auto& h : hexahedra) volume += signedVolume(points, h);
  EXPECT_NEAR(volume, 6.0, 1e-12);
}

TEST(RegularGrid, QuadsAndEdgesCountEveryGridFaceAndSegment) {
  const GridSize n{3, 3, 3};
  const auto quads = makeGridQuads(n);
  EXPECT_EQ(quads.size(), 36u);  // 3 planes x 4 quads x 3 directions
  const auto edges = makeGridEdges(n);
  EXPECT_EQ(edges.size(), 54u);  // 9 lines x 2 segments x 3 directions
  // The same sets as the adjacency of the hexahedra.
  const auto hexahedra = makeGridHexahedra(n);
  EXPECT_EQ(computeHexahedronFaces(hexahedra).faces.size(), quads.size());
  EXPECT_EQ(computeHexahedronEdges(hexahedra).edges.size(), edges.size());
  std::set<std::array<Index, 4>> unique;
  for (Quad q : quads) {
    std::sort(q.begin(), q.end());
    unique.insert(q);
  }
  EXPECT_EQ(unique.size(), quads.size());
}

TEST(RegularGrid, FlatGrids) {
  const GridSize plane{3, 3, 1};
  EXPECT_TRUE(makeGridHexahedra(plane).empty());
  EXPECT_EQ(makeGridQuads(plane).size(), 4u);
  EXPECT_EQ(makeGridEdges(plane).size(), 12u);
  const GridSize line{5, 1, 1};
  EXPECT_TRUE(makeGridQuads(line).empty());
  EXPECT_EQ(makeGridEdges(line).size(), 4u);
}

}  // namespace
}  // namespace stroma::test
