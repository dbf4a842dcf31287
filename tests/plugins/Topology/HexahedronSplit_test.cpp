// SPDX-License-Identifier: MIT
// Splitting hexahedra into tetrahedra: every tetrahedron positive, the volumes summing to the
// grid's, and a conforming result (neighbours share whole triangles: the boundary has exactly
// two triangles per boundary quad, and no face belongs to more than two tetrahedra).
#include "HexahedronSplit.h"

#include <gtest/gtest.h>

#include "topology/MeshAdjacency.h"
#include "topology/MeshGeometry.h"

namespace stroma::test {
namespace {

struct Grid {
  std::vector<Vec3d> points;
  std::vector<Hexahedron> hexahedra;
};

Grid grid(int nx, int ny, int nz, const Vec3d& spacing) {
  const GridSize n{nx + 1, ny + 1, nz + 1};
  return {makeGridPoints(n, Vec3d(-1, 2, 0.5), spacing), makeGridHexahedra(n)};
}

void expectConformingPositiveSplit(const Grid& g, const std::vector<Tetrahedron>& tets,
                                   double expectedVolume, const std::string& what) {
  double volume = 0;
  for (const Tetrahedron& t : tets) {
    const double v = signedVolume(g.points, t);
    EXPECT_GT(v, 0) << what;
    volume += v;
  }
  EXPECT_NEAR(volume, expectedVolume, 1e-12 * expectedVolume) << what;
  EXPECT_TRUE(checkTetrahedra(g.points, tets).empty()) << what;
  const TetrahedronFaces faces = computeTetrahedronFaces(tets);
  for (std::size_t f = 0; f < faces.faces.size(); ++f)
    EXPECT_LE(faces.elementsAroundFace[f].size(), 2u) << what;
  EXPECT_EQ(computeBoundaryTriangles(tets).size(), 2 * computeBoundaryQuads(g.hexahedra).size())
      << what;
}

TEST(HexahedronSplit, SixPerHexahedronAsSofa) {
  const Grid g = grid(3, 2, 2, Vec3d(0.5, 1, 2));
  const auto tets = splitHexahedraInSix(g.hexahedra);
  ASSERT_EQ(tets.size(), 6 * g.hexahedra.size());
  expectConformingPositiveSplit(g, tets, 1.5 * 2 * 4, "six");
}

TEST(HexahedronSplit, SixWithAlternatingMirrors) {
  const Grid g = grid(3, 3, 2, Vec3d(1, 1, 1));
  const auto cells = findGridCells(g.hexahedra);
  ASSERT_TRUE(cells);
  EXPECT_EQ(cells->nx, 3);
  EXPECT_EQ(cells->ny, 3);
  EXPECT_EQ(cells->nz, 2);
  const auto mirrors = alternatingMirrors(*cells);
  ASSERT_EQ(mirrors.size(), g.hexahedra.size());
  const auto tets = splitHexahedraInSix(g.hexahedra, mirrors);
  expectConformingPositiveSplit(g, tets, 18, "six mirrored");
  // The mirrored split differs from the plain one: the diagonals alternate.
  EXPECT_NE(tets, splitHexahedraInSix(g.hexahedra));
  // Every single mirror combination is positive on its own.
  const Grid one = grid(1, 1, 1, Vec3d(1, 2, 3));
  for (std::uint8_t m = 0; m < 8; ++m) {
    const std::uint8_t bits[] = {m};
    expectConformingPositiveSplit(one, splitHexahedraInSix(one.hexahedra, bits), 6,
                                  "mirror " + std::to_string(m));
  }
}

TEST(HexahedronSplit, FiveAlternatingBetweenNeighbours) {
  const Grid g = grid(3, 2, 3, Vec3d(1, 0.5, 1));
  const FiveSplit split = splitHexahedraInFive(g.hexahedra);
  EXPECT_EQ(split.mismatchedFaces, 0u);
  ASSERT_EQ(split.tetrahedra.size(), 5 * g.hexahedra.size());
  expectConformingPositiveSplit(g, split.tetrahedra, 9, "five");
}

TEST(HexahedronSplit, FiveSplitReportsFacesThatCannotMatch) {
  // The variants alternate like a two-colouring of the points, which a ring of three
  // hexahedra (a torus of three sections) does not have: the points along the ring make
  // cycles of three edges.
  std::vector<Hexahedron> ring;
  for (Index s = 0; s < 3; ++s) {
    const Index t = (s + 1) % 3;
    ring.push_back(
        {4 * s, 4 * s + 1, 4 * s + 2, 4 * s + 3, 4 * t, 4 * t + 1, 4 * t + 2, 4 * t + 3});
  }
  EXPECT_EQ(computeHexahedronFaces(ring).faces.size(), 3u * 6u - 3u);
  EXPECT_GT(splitHexahedraInFive(ring).mismatchedFaces, 0u);
  // Four sections: the colouring exists again.
  std::vector<Hexahedron> even;
  for (Index s = 0; s < 4; ++s) {
    const Index t = (s + 1) % 4;
    even.push_back(
        {4 * s, 4 * s + 1, 4 * s + 2, 4 * s + 3, 4 * t, 4 * t + 1, 4 * t + 2, 4 * t + 3});
  }
  EXPECT_EQ(splitHexahedraInFive(even).mismatchedFaces, 0u);
}

TEST(HexahedronSplit, FindGridCellsRefusesOtherNumberings) {
  Grid g = grid(2, 2, 2, Vec3d(1, 1, 1));
  EXPECT_TRUE(findGridCells(g.hexahedra));
  std::swap(g.hexahedra[1], g.hexahedra[2]);
  EXPECT_FALSE(findGridCells(g.hexahedra));
  EXPECT_FALSE(findGridCells({}));
}

}  // namespace
}  // namespace stroma::test
