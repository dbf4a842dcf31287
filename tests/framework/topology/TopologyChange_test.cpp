// SPDX-License-Identifier: MIT
// Removing tetrahedra from a topology (TopologyChange.h): SOFA's renumbering, the triangles and
// edges that go with them, the change log and its revisions, and bad input; removing the
// triangles of a surface.
#include "topology/TopologyChange.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "framework/topology/CubeMeshes.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

class PlainTopology final : public Topology {};

std::size_t countMessages(const Base& b, MessageLevel level) {
  std::size_t n = 0;
  for (const Message& m : b.messageLog().messages()) n += m.level == level;
  return n;
}

/// The unit cube in six tetrahedra, with its faces and edges listed as a set container does.
void fillCube(Topology& t) {
  t.d_position.setValue(unitCubePoints());
  t.d_tetrahedra.setValue(cubeInSixTetrahedra());
  t.d_triangles.setValue(std::vector<Triangle>(t.tetrahedronFaces().faces));
  t.d_edges.setValue(computeAllEdges({}, {}, {}, t.tetrahedra(), {}));
}

template <std::size_t N>
std::set<std::array<Index, N>> sortedSet(const std::vector<std::array<Index, N>>& elements) {
  std::set<std::array<Index, N>> out;
  for (auto e : elements) {
    std::sort(e.begin(), e.end());
    out.insert(e);
  }
  return out;
}

TEST(TopologyChange, LastElementMovesIntoEachRemovedSlot) {
  PlainTopology t;
  fillCube(t);
  const std::uint64_t r0 = t.revision();
  std::string error;
  const std::vector<Index> remove{1, 4, 1};  // duplicates count once
  ASSERT_TRUE(t.removeTetrahedra(remove, error)) << error;

  // Remove 4 (5 moves into it), then 1 (the last, old 5, moves into it).
  const auto six = cubeInSixTetrahedra();
  EXPECT_EQ(t.tetrahedra(), (std::vector<Tetrahedron>{six[0], six[5], six[2], six[3]}));
  EXPECT_EQ(t.revision(), r0 + 1);
  const auto changes = t.changesSince(r0);
  ASSERT_TRUE(changes.has_value());
  ASSERT_EQ(changes->size(), 1u);
  const TopologyChange& change = (*changes)[0];
  EXPECT_EQ(change.revision, r0 + 1);
  EXPECT_EQ(change.tetrahedra.removed, (std::vector<Index>{4, 1}));
  EXPECT_EQ(change.tetrahedra.removedElements, (std::vector<Tetrahedron>{six[4], six[1]}));
  EXPECT_EQ(change.tetrahedra.moved, (std::vector<std::pair<Index, Index>>{{5, 1}}));
  EXPECT_EQ(change.tetrahedra.sizeBefore, 6u);
  EXPECT_EQ(change.tetrahedra.sizeAfter, 4u);

  // Replaying the removal on per-element data gives the new order.
  std::vector<int> original{0, 1, 2, 3, 4, 5};
  applyRemoval(original, change.tetrahedra.removed);
  EXPECT_EQ(original, (std::vector<int>{0, 5, 2, 3}));

  // Two boundary faces of each removed tetrahedron go; the faces they shared stay. Edges 2-3
  // and 4-5 belonged to them only. No point is left without a tetrahedron.
  EXPECT_EQ(change.triangles.removed.size(), 4u);
  EXPECT_EQ(t.triangles().size(), 18u - 4u);
  EXPECT_EQ(sortedSet(change.edges.removedElements),
            (std::set<std::array<Index, 2>>{{2, 3}, {4, 5}}));
  EXPECT_TRUE(change.freedPoints.empty());
  EXPECT_EQ(sortedSet(t.triangles()), sortedSet(t.tetrahedronFaces().faces));
  EXPECT_EQ(sortedSet(t.edges()), sortedSet(t.tetrahedronEdges().edges));
  // The points stay.
  EXPECT_EQ(t.positions().size(), 8u);
  EXPECT_EQ(countMessages(t, MessageLevel::warning), 0u);
}

TEST(TopologyChange, RandomRemovalsMatchTheListsRebuiltFromScratch) {
  // 3 x 3 x 3 cubes, six tetrahedra each, removed a few at a time in random order.
  const HexGrid grid = hexGrid(3);
  std::vector<Tetrahedron> tetrahedra;
  for (const Hexahedron& h : grid.hexahedra)
    for (const Tetrahedron& local : cubeInSixTetrahedra())
      tetrahedra.push_back({h[local[0]], h[local[1]], h[local[2]], h[local[3]]});
  PlainTopology t;
  t.d_position.setValue(grid.points);
  t.d_tetrahedra.setValue(tetrahedra);
  t.d_triangles.setValue(std::vector<Triangle>(t.tetrahedronFaces().faces));
  t.d_edges.setValue(computeAllEdges({}, {}, {}, t.tetrahedra(), {}));

  // Per-element data: the original index of each tetrahedron, triangle, edge.
  std::vector<Tetrahedron> tetraIds = t.tetrahedra();
  std::vector<Triangle> triangleIds = t.triangles();
  std::vector<Edge> edgeIds = t.edges();
  std::mt19937 random(7);
  std::set<Index> freed;
  while (!t.tetrahedra().empty()) {
    const std::uint64_t before = t.revision();
    std::vector<Index> batch;
    const std::size_t n = t.tetrahedra().size();
    for (int k = 0; k < 3; ++k) batch.push_back(static_cast<Index>(random() % n));
    std::string error;
    ASSERT_TRUE(t.removeTetrahedra(batch, error)) << error;
    const auto changes = t.changesSince(before);
    ASSERT_TRUE(changes && changes->size() == 1);
    const TopologyChange& change = (*changes)[0];
    applyRemoval(tetraIds, change.tetrahedra.removed);
    applyRemoval(triangleIds, change.triangles.removed);
    applyRemoval(edgeIds, change.edges.removed);
    EXPECT_EQ(tetraIds, t.tetrahedra());
    EXPECT_EQ(triangleIds, t.triangles());
    EXPECT_EQ(edgeIds, t.edges());
    // `moved` is the net renumbering.
    for (const auto& [from, to] : change.tetrahedra.moved) {
      EXPECT_GE(from, change.tetrahedra.sizeAfter);
      EXPECT_LT(to, change.tetrahedra.sizeAfter);
    }
    EXPECT_EQ(sortedSet(t.triangles()), sortedSet(t.tetrahedronFaces().faces));
    EXPECT_EQ(sortedSet(t.edges()), sortedSet(t.tetrahedronEdges().edges));
    freed.insert(change.freedPoints.begin(), change.freedPoints.end());
    const auto& around = t.tetrahedraAroundVertex();
    for (Index p = 0; p < grid.points.size(); ++p)
      EXPECT_EQ(freed.contains(p), around[p].empty()) << "point " << p;
  }
  EXPECT_TRUE(t.triangles().empty());
  EXPECT_TRUE(t.edges().empty());
  EXPECT_EQ(freed.size(), grid.points.size());
  EXPECT_EQ(t.positions().size(), grid.points.size());
}

TEST(TopologyChange, ChangesMadeAnotherWayAreNotLogged) {
  PlainTopology t;
  fillCube(t);
  const std::uint64_t r0 = t.revision();
  std::string error;
  ASSERT_TRUE(t.removeTetrahedra(std::vector<Index>{0}, error));
  const std::uint64_t r1 = t.revision();
  ASSERT_TRUE(t.removeTetrahedra(std::vector<Index>{0}, error));
  ASSERT_EQ(t.changesSince(r0)->size(), 2u);
  EXPECT_EQ(t.changesSince(r1)->size(), 1u);
  EXPECT_TRUE(t.changesSince(t.revision())->empty());
  // Elements set directly: a new revision without a log entry, so readers must rebuild.
  t.d_tetrahedra.setValue(cubeInFiveTetrahedra());
  EXPECT_FALSE(t.changesSince(r1).has_value());
  const std::uint64_t r3 = t.revision();
  ASSERT_TRUE(t.removeTetrahedra(std::vector<Index>{2}, error));
  EXPECT_EQ(t.changesSince(r3)->size(), 1u);
  EXPECT_FALSE(t.changesSince(r0).has_value());
}

TEST(TopologyChange, TheLogKeepsTheLastChanges) {
  PlainTopology t;
  t.d_tetrahedra.setValue(std::vector<Tetrahedron>(200, Tetrahedron{0, 1, 2, 3}));
  const std::uint64_t r0 = t.revision();
  std::string error;
  for (std::size_t k = 0; k < Topology::kChangeLogCapacity + 10; ++k)
    ASSERT_TRUE(t.removeTetrahedra(std::vector<Index>{0}, error));
  EXPECT_FALSE(t.changesSince(r0).has_value());
  EXPECT_EQ(t.changesSince(t.revision() - 5)->size(), 5u);
}

TEST(TopologyChange, AnIndexThatDoesNotExistChangesNothing) {
  PlainTopology t;
  fillCube(t);
  const std::uint64_t r0 = t.revision();
  std::string error;
  EXPECT_FALSE(t.removeTetrahedra(std::vector<Index>{2, 6}, error));
  EXPECT_NE(error.find("tetrahedron 6 does not exist"), std::string::npos) << error;
  EXPECT_NE(error.find("indices 0 to 5"), std::string::npos) << error;
  EXPECT_EQ(t.tetrahedra().size(), 6u);
  EXPECT_EQ(t.revision(), r0);
  // Nothing to remove: no change, no revision.
  EXPECT_TRUE(t.removeTetrahedra(std::vector<Index>{}, error));
  EXPECT_EQ(t.revision(), r0);
}

TEST(TopologyChange, RemovingEverythingFreesThePointsWithOneWarning) {
  PlainTopology t;
  fillCube(t);
  std::string error;
  ASSERT_TRUE(t.removeTetrahedra(std::vector<Index>{0}, error));
  EXPECT_EQ(countMessages(t, MessageLevel::warning), 0u);
  const std::uint64_t before = t.revision();
  ASSERT_TRUE(t.removeTetrahedra(std::vector<Index>{0, 1, 2, 3, 4}, error));
  EXPECT_TRUE(t.tetrahedra().empty());
  EXPECT_TRUE(t.triangles().empty());
  EXPECT_TRUE(t.edges().empty());
  EXPECT_EQ((*t.changesSince(before))[0].freedPoints, (std::vector<Index>{0, 1, 2, 3, 4, 5, 6, 7}));
  ASSERT_EQ(countMessages(t, MessageLevel::warning), 1u);
  EXPECT_NE(t.messageLog().messages().back().text.find("no stiffness"), std::string::npos);
  // Once only.
  t.d_tetrahedra.setValue(cubeInSixTetrahedra());
  ASSERT_TRUE(t.removeTetrahedra(std::vector<Index>{0, 1, 2, 3, 4, 5}, error));
  EXPECT_EQ(countMessages(t, MessageLevel::warning), 1u);
  EXPECT_FALSE(t.removeTetrahedra(std::vector<Index>{0}, error));
  EXPECT_NE(error.find("there are 0 tetrahedra"), std::string::npos) << error;
}

}  // namespace
}  // namespace stroma::test

namespace stroma::test {
namespace {

/// Removing the triangles of a surface: SOFA's renumbering, the edges no remaining triangle
/// uses, the freed points, a change that is not logged, and a bad index.
TEST(TopologyChange, RemovingTrianglesOfASurface) {
  // A strip of 3 squares, two triangles each, points 0-3 below and 4-7 above.
  PlainTopology t;
  const std::vector<Triangle> strip{{0, 1, 5}, {0, 5, 4}, {1, 2, 6},
                                    {1, 6, 5}, {2, 3, 7}, {2, 7, 6}};
  t.d_triangles.setValue(strip);
  t.d_edges.setValue(computeAllEdges({}, t.triangles(), {}, {}, {}));
  ASSERT_EQ(t.edges().size(), 13u);
  const std::uint64_t r0 = t.revision();
  std::string error;
  // The last square and one triangle of the first.
  const std::vector<Index> remove{4, 5, 0, 5};
  ASSERT_TRUE(t.removeTriangles(remove, error)) << error;
  // Remove 5 (the last), then 4 (now the last), then 0 (old 3 moves into it).
  EXPECT_EQ(t.triangles(), (std::vector<Triangle>{strip[3], strip[1], strip[2]}));
  // Gone: 2-3, 3-7, 2-7 (the last square's diagonal), 6-7 and 0-1 (side of triangle 0 only).
  const auto edges = sortedSet<2>(t.edges());
  EXPECT_EQ(edges.size(), 8u);
  for (const Edge e : std::vector<Edge>{{2, 3}, {3, 7}, {2, 7}, {6, 7}, {0, 1}})
    EXPECT_FALSE(edges.contains(e)) << e[0] << "-" << e[1];
  for (const Edge e : std::vector<Edge>{{1, 5}, {0, 5}, {2, 6}, {1, 2}, {5, 6}})
    EXPECT_TRUE(edges.contains(e)) << e[0] << "-" << e[1];
  EXPECT_EQ(countMessages(t, MessageLevel::warning), 1u);  // points 3 and 7 are free
  EXPECT_NE(t.messageLog().messages().back().text.find("2 points belong to no triangle"),
            std::string::npos);
  // A new revision, not logged: the components rebuild.
  EXPECT_EQ(t.revision(), r0 + 1);
  EXPECT_FALSE(t.changesSince(r0).has_value());

  // A bad index changes nothing.
  const std::vector<Index> bad{0, 3};
  EXPECT_FALSE(t.removeTriangles(bad, error));
  EXPECT_NE(error.find("triangle 3 does not exist (there are 3 triangles"), std::string::npos)
      << error;
  EXPECT_EQ(t.triangles().size(), 3u);
  EXPECT_EQ(t.revision(), r0 + 1);

  // The triangles of a volume are its tetrahedra's faces: not removed alone.
  PlainTopology cube;
  fillCube(cube);
  EXPECT_FALSE(cube.removeTriangles(std::vector<Index>{0}, error));
  EXPECT_NE(error.find("remove tetrahedra instead"), std::string::npos) << error;
}

}  // namespace
}  // namespace stroma::test
