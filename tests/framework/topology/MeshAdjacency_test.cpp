// SPDX-License-Identifier: MIT
// The adjacency kernels on meshes whose answers are known: the unit cube split into 5 and 6
// tetrahedra, a 2x2x2 grid of hexahedra, a square of two triangles.
#include "topology/MeshAdjacency.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "framework/topology/CubeMeshes.h"
#include "topology/MeshGeometry.h"

namespace stroma::test {
namespace {

Vec3d faceNormal(const std::vector<Vec3d>& p, const Triangle& t) {
  return (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
}

Vec3d centroid(const std::vector<Vec3d>& p, const auto& element) {
  Vec3d c = Vec3d::Zero();
  for (Index v : element) c += p[v];
  return c / double(element.size());
}

/// Every boundary triangle of the cube lies on a cube face and points out of the cube.
void expectOutwardCubeBoundary(const std::vector<Triangle>& boundary) {
  const auto p = unitCubePoints();
  const Vec3d centre(0.5, 0.5, 0.5);
  double area = 0;
  for (const Triangle& t : boundary) {
    const Vec3d n = faceNormal(p, t);
    EXPECT_GT(n.dot(centroid(p, t) - centre), 0) << t[0] << " " << t[1] << " " << t[2];
    // On a face of the cube: the normal is along an axis.
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), n.norm(), 1e-12);
    area += n.norm() / 2;
  }
  EXPECT_NEAR(area, 6.0, 1e-12);  // the cube's surface
}

TEST(MeshAdjacency, CubeOfFiveTetrahedra) {
  const auto tets = cubeInFiveTetrahedra();
  for (const auto& t : tets) EXPECT_GT(signedVolume(unitCubePoints(), t), 0);

  const TetrahedronFaces faces = computeTetrahedronFaces(tets);
  EXPECT_EQ(faces.faces.size(), 16u);  // 20 face slots, the central tetrahedron's 4 shared
  ASSERT_EQ(faces.facesInElement.size(), 5u);
  ASSERT_EQ(faces.elementsAroundFace.size(), 16u);
  for (Index f : faces.facesInElement[4]) EXPECT_EQ(faces.elementsAroundFace[f].size(), 2u);

  const std::vector<Triangle> boundary = computeBoundaryTriangles(tets);
  EXPECT_EQ(boundary.size(), 12u);
  expectOutwardCubeBoundary(boundary);

  const ElementEdges<6> edges = computeTetrahedronEdges(tets);
  EXPECT_EQ(edges.edges.size(), 18u);  // 12 cube edges and 6 face diagonals
}

TEST(MeshAdjacency, CubeOfSixTetrahedra) {
  const auto tets = cubeInSixTetrahedra();
  for (const auto& t : tets) EXPECT_GT(signedVolume(unitCubePoints(), t), 0);
  const TetrahedronFaces faces = computeTetrahedronFaces(tets);
  EXPECT_EQ(faces.faces.size(), 18u);  // 12 boundary + 6 inside
  const std::vector<Triangle> boundary = computeBoundaryTriangles(tets);
  EXPECT_EQ(boundary.size(), 12u);
  expectOutwardCubeBoundary(boundary);
  EXPECT_EQ(computeTetrahedronEdges(tets).edges.size(), 19u);  // and the 0-6 diagonal
}

TEST(MeshAdjacency, FaceOrderIsFirstAppearanceAndOutwardFromFirstTetrahedron) {
  const auto tets = cubeInSixTetrahedra();
  const TetrahedronFaces faces = computeTetrahedronFaces(tets);
  // The first tetrahedron's faces come first, in the local order of kTetrahedronFaces.
  for (int j = 0; j < 4; ++j) {
    EXPECT_EQ(faces.facesInElement[0][j], Index(j));
    Triangle expected;
    for (int k = 0; k < 3; ++k) expected[k] = tets[0][kTetrahedronFaces[j][k]];
    EXPECT_EQ(faces.faces[j], expected);
  }
  // The same result twice (deterministic).
  const TetrahedronFaces again = computeTetrahedronFaces(tets);
  EXPECT_EQ(again.faces, faces.faces);
  EXPECT_EQ(again.facesInElement, faces.facesInElement);
}

TEST(MeshAdjacency, LocalFaceTablesAreOutwardForAPositiveElement) {
  const auto p = unitCubePoints();
  const Tetrahedron t{0, 1, 3, 4};  // positive corner tetrahedron
  ASSERT_GT(signedVolume(p, t), 0);
  for (int j = 0; j < 4; ++j) {
    const Triangle f{t[kTetrahedronFaces[j][0]], t[kTetrahedronFaces[j][1]],
                     t[kTetrahedronFaces[j][2]]};
    EXPECT_LT(faceNormal(p, f).dot(p[t[j]] - centroid(p, f)), 0) << "face " << j;
  }
  const Hexahedron h{0, 1, 2, 3, 4, 5, 6, 7};
  for (int j = 0; j < 6; ++j) {
    const Quad q{h[kHexahedronFaces[j][0]], h[kHexahedronFaces[j][1]], h[kHexahedronFaces[j][2]],
                 h[kHexahedronFaces[j][3]]};
    const Vec3d n = (p[q[1]] - p[q[0]]).cross(p[q[3]] - p[q[0]]);
    EXPECT_GT(n.dot(centroid(p, q) - Vec3d(0.5, 0.5, 0.5)), 0) << "face " << j;
  }
}

TEST(MeshAdjacency, GridOfTwoByTwoByTwoHexahedra) {
  const HexGrid grid = hexGrid(2);
  ASSERT_EQ(grid.points.size(), 27u);
  ASSERT_EQ(grid.hexahedra.size(), 8u);
  const HexahedronFaces faces = computeHexahedronFaces(grid.hexahedra);
  EXPECT_EQ(faces.faces.size(), 36u);  // 3 directions x 3 planes x 4 quads
  const std::vector<Quad> boundary = computeBoundaryQuads(grid.hexahedra);
  EXPECT_EQ(boundary.size(), 24u);
  const Vec3d centre(1, 1, 1);
  for (const Quad& q : boundary) {
    const Vec3d n =
        (grid.points[q[1]] - grid.points[q[0]]).cross(grid.points[q[3]] - grid.points[q[0]]);
    EXPECT_GT(n.dot(centroid(grid.points, q) - centre), 0);
  }
  EXPECT_EQ(computeHexahedronEdges(grid.hexahedra).edges.size(), 54u);  // 3 x 3 x 3 x 2

  // The centre point (index 13) is in every hexahedron and on 6 edges.
  const AdjacencyList around = computeElementsAroundVertex<8>(grid.hexahedra, 27);
  ASSERT_EQ(around.size(), 27u);
  EXPECT_EQ(around[13].size(), 8u);
  EXPECT_TRUE(std::is_sorted(around[13].begin(), around[13].end()));
  EXPECT_EQ(around[0].size(), 1u);  // a corner of the grid
  const std::vector<Edge> edges = computeHexahedronEdges(grid.hexahedra).edges;
  const AdjacencyList edgesAround = computeElementsAroundVertex<2>(edges, 27);
  EXPECT_EQ(edgesAround[13].size(), 6u);
  EXPECT_EQ(edgesAround[0].size(), 3u);
}

TEST(MeshAdjacency, TetrahedraAroundVertexOfTheCube) {
  const auto tets = cubeInSixTetrahedra();
  const AdjacencyList around = computeElementsAroundVertex<4>(tets, 8);
  EXPECT_EQ(around[0].size(), 6u);  // on the diagonal: every tetrahedron
  EXPECT_EQ(around[6].size(), 6u);
  EXPECT_EQ(std::vector<Index>(around[1].begin(), around[1].end()), (std::vector<Index>{0, 5}));
  // Points past nbPoints are skipped, not written out of bounds.
  const AdjacencyList fewer = computeElementsAroundVertex<4>(tets, 3);
  EXPECT_EQ(fewer.size(), 3u);
}

TEST(MeshAdjacency, EdgesOfTrianglesAndBorder) {
  const std::vector<Triangle> square{{0, 1, 2}, {0, 2, 3}};
  const ElementEdges<3> edges = computeTriangleEdges(square);
  EXPECT_EQ(edges.edges.size(), 5u);
  EXPECT_EQ(edges.edges[0], (Edge{1, 2}));  // edge 0 is opposite vertex 0
  const std::vector<Edge> border = computeBoundaryEdges(square);
  EXPECT_EQ(border.size(), 4u);
  for (const Edge& e : border) EXPECT_FALSE((e == Edge{0, 2} || e == Edge{2, 0}));
}

TEST(MeshAdjacency, AllEdgesKeepsGivenEdgesFirstWithoutDuplicates) {
  const std::vector<Edge> given{{2, 1}, {5, 6}};
  const std::vector<Triangle> triangles{{0, 1, 2}};
  const std::vector<Edge> all = computeAllEdges(given, triangles, {}, {}, {});
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[0], (Edge{2, 1}));
  EXPECT_EQ(all[1], (Edge{5, 6}));
  std::set<std::pair<Index, Index>> unique;
  for (const Edge& e : all) unique.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  EXPECT_EQ(unique.size(), all.size());
}

TEST(MeshAdjacency, EmptyInputsGiveEmptyResults) {
  EXPECT_TRUE(computeTetrahedronFaces({}).faces.empty());
  EXPECT_TRUE(computeBoundaryQuads({}).empty());
  EXPECT_EQ(computeElementsAroundVertex<4>({}, 0).size(), 0u);
}

}  // namespace
}  // namespace stroma::test
