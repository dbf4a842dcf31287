// SPDX-License-Identifier: MIT
// GridMeshCreator: the element counts of an nx x ny grid in closed form for every pattern,
// counter-clockwise triangles covering the unit square, runSofa's own output for a 4 x 3 grid
// (points, alternate triangles and edges, from its VTK export), the placement, and an error
// naming `resolution` for a grid of one point per row.
#include <gtest/gtest.h>

#include "GridMeshCreator.h"
#include "plugins/MeshIO/SceneFixture.h"

namespace stroma::test {
namespace {

double signedArea(const MeshData& m, const Triangle& t) {
  const Vec3d a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
  return 0.5 * (b - a).cross(c - a).z();
}

TEST(GridMeshCreator, ElementCountsAreTheClosedForms) {
  for (int nx : {2, 3, 7})
    for (int ny : {2, 5}) {
      const int cells = (nx - 1) * (ny - 1);
      for (auto pattern : {GridTrianglePattern::alternate, GridTrianglePattern::upward,
                           GridTrianglePattern::downward}) {
        const MeshData m = makeGridMesh(nx, ny, pattern);
        EXPECT_EQ(m.positions.size(), std::size_t(nx * ny));
        EXPECT_EQ(m.triangles.size(), std::size_t(2 * cells));
        EXPECT_TRUE(m.quads.empty());
        // Horizontal, vertical and one diagonal per cell.
        EXPECT_EQ(m.edges.size(), std::size_t((nx - 1) * ny + nx * (ny - 1) + cells));
        double area = 0;
        for (const Triangle& t : m.triangles) {
          EXPECT_GT(signedArea(m, t), 0);
          area += signedArea(m, t);
        }
        EXPECT_NEAR(area, 1.0, 1e-14);
      }
      const MeshData q = makeGridMesh(nx, ny, GridTrianglePattern::quads);
      EXPECT_EQ(q.quads.size(), std::size_t(cells));
      EXPECT_EQ(q.edges.size(), std::size_t((nx - 1) * ny + nx * (ny - 1)));
    }
}

TEST(GridMeshCreator, MatchesRunSofaOnA4By3AlternateGrid) {
  const MeshData m = makeGridMesh(4, 3, GridTrianglePattern::alternate);
  EXPECT_TRUE(m.positions[5].isApprox(Vec3d(1.0 / 3, 0.5, 0)));
  const std::vector<Triangle> triangles = {{0, 1, 5}, {0, 5, 4},  {1, 2, 5},  {2, 6, 5},
                                           {2, 3, 7}, {2, 7, 6},  {4, 5, 8},  {5, 9, 8},
                                           {5, 6, 10}, {5, 10, 9}, {6, 7, 10}, {7, 11, 10}};
  EXPECT_EQ(m.triangles, triangles);
  const std::vector<Edge> edges = {{0, 1}, {1, 2},  {1, 5},  {2, 3},  {2, 5},  {2, 6},
                                   {3, 7}, {4, 0},  {5, 0},  {5, 4},  {5, 8},  {5, 9},
                                   {6, 5}, {6, 10}, {7, 2},  {7, 6},  {7, 10}, {7, 11},
                                   {8, 4}, {9, 8},  {10, 5}, {10, 9}, {11, 10}};
  EXPECT_EQ(m.edges, edges);
  const MeshData down = makeGridMesh(4, 3, GridTrianglePattern::downward);
  EXPECT_EQ(down.triangles[0], (Triangle{0, 1, 4}));
  EXPECT_EQ(down.triangles[1], (Triangle{1, 5, 4}));
}

using GridMeshCreatorScene = SceneFixture;

TEST_F(GridMeshCreatorScene, PlacesTheGridAndFeedsATopology) {
  ASSERT_TRUE(load(R"(<Node name="root">
  <GridMeshCreator name="loader" filename="nofile" resolution="3 2" trianglePattern="0"
                   scale3d="2 4 1" translation="1 0 5"/>
  <MeshTopology name="topo" src="@loader"/>
</Node>)")) << messages();
  EXPECT_EQ(value("/loader", "position"), "1 0 5 2 0 5 3 0 5 1 4 5 2 4 5 3 4 5");
  EXPECT_EQ(value("/loader", "quads"), "0 1 4 3 1 2 5 4");
  EXPECT_EQ(topology("/topo")->d_quads.value().size(), 2u);
}

TEST_F(GridMeshCreatorScene, OnePointAlongAnAxisIsAnError) {
  EXPECT_FALSE(load(R"(<Node name="root"><GridMeshCreator resolution="1 4"/></Node>)"));
  EXPECT_EQ(find(MessageLevel::error, "at least 2 points").field, "resolution");
}

}  // namespace
}  // namespace stroma::test
