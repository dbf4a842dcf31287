// SPDX-License-Identifier: MIT
// makeMixedGrid: the hexahedra of a grid refined in part, and its T-nodes (fine nodes on a kept
// coarse cell's edge or face) with parents whose interpolation gives the node's position.
#include "MultiresolutionGrid.h"

#include <gtest/gtest.h>

namespace stroma::multiresolution {
namespace {

double volume(const std::vector<Vec3d>& p, const Hexahedron& h) {
  // The cells are boxes: the diagonal from vertex 0 to vertex 6.
  const Vec3d d = p[h[6]] - p[h[0]];
  return d.x() * d.y() * d.z();
}

TEST(MultiresolutionGrid, TwoCellsOneRefinedHaveFiveTNodesOnTheirCommonFace) {
  // 2 x 1 x 1 cells of size 1, the second refined: its face x = 1 is the first cell's, with
  // 3 x 3 fine nodes of which 4 are coarse corners; 4 edge midpoints and the centre are T-nodes.
  const MixedGrid g = makeMixedGrid({3, 2, 2}, Vec3d(0, 0, 0), Vec3d(2, 1, 1), {0, 1});
  EXPECT_EQ(g.hexahedra.size(), 1u + 8u);
  EXPECT_EQ(g.points.size(), 8u + 27u - 4u);
  double total = 0;
  for (const Hexahedron& h : g.hexahedra) {
    EXPECT_GT(volume(g.points, h), 0);
    total += volume(g.points, h);
  }
  EXPECT_NEAR(total, 2.0, 1e-14);
  ASSERT_EQ(g.tNodes.size(), 5u);
  int edges = 0, faces = 0;
  for (const TNode& t : g.tNodes) {
    EXPECT_NEAR(g.points[t.node].x(), 1.0, 1e-15);
    double sum = 0;
    Vec3d interpolated = Vec3d::Zero();
    for (int k = 0; k < t.parentCount; ++k) {
      sum += t.weights[k];
      interpolated += t.weights[k] * g.points[t.parents[k]];
      // Parents are corners of the kept cell.
      EXPECT_NEAR(g.points[t.parents[k]].x(), 1.0, 1e-15);
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_LT((interpolated - g.points[t.node]).norm(), 1e-15);
    (t.parentCount == 2 ? edges : faces) += 1;
  }
  EXPECT_EQ(edges, 4);
  EXPECT_EQ(faces, 1);
}

TEST(MultiresolutionGrid, AllOrNothingRefinedHasNoTNodes) {
  const MixedGrid coarse =
      makeMixedGrid({3, 3, 3}, Vec3d::Zero(), Vec3d::Ones(), std::vector<char>(8, 0));
  const MixedGrid fine =
      makeMixedGrid({3, 3, 3}, Vec3d::Zero(), Vec3d::Ones(), std::vector<char>(8, 1));
  EXPECT_EQ(coarse.points.size(), 27u);
  EXPECT_EQ(fine.points.size(), 125u);
  EXPECT_EQ(fine.hexahedra.size(), 64u);
  EXPECT_TRUE(coarse.tNodes.empty());
  EXPECT_TRUE(fine.tNodes.empty());
}

TEST(MultiresolutionGrid, ACornerCellRefinedHasTNodesOnItsThreeInnerFaces) {
  // 2 x 2 x 2 cells, cell 0 refined: its three faces shared with kept cells hold 3 face centres
  // and the edge midpoints of those faces: 9 edges in all (3 inner ones counted once), and the
  // refined cell's edges on the outer boundary of the grid, next to kept cells, too.
  std::vector<char> refined(8, 0);
  refined[0] = 1;
  const MixedGrid g = makeMixedGrid({3, 3, 3}, Vec3d::Zero(), Vec3d(2, 2, 2), refined);
  int faces = 0;
  for (const TNode& t : g.tNodes) {
    faces += t.parentCount == 4;
    Vec3d interpolated = Vec3d::Zero();
    for (int k = 0; k < t.parentCount; ++k) interpolated += t.weights[k] * g.points[t.parents[k]];
    EXPECT_LT((interpolated - g.points[t.node]).norm(), 1e-15);
  }
  EXPECT_EQ(faces, 3);
  // Fine nodes of cell 0 with some coordinate 1 (on a face towards a kept cell), not coarse.
  EXPECT_EQ(g.tNodes.size(), 3u /*face centres*/ + 9u /*edge midpoints*/);
}

}  // namespace
}  // namespace stroma::multiresolution
