// SPDX-License-Identifier: MIT
// The Topology interface: accessors, cached adjacency and its revision, and the checks.
#include "topology/Topology.h"

#include <gtest/gtest.h>

#include "framework/topology/CubeMeshes.h"

namespace stroma::test {
namespace {

/// A Topology with nothing added, and its checks callable.
class PlainTopology final : public Topology {
 public:
  bool check() { return checkElements(); }
};

std::vector<Message> messagesOf(const Base& b, MessageLevel level) {
  std::vector<Message> result;
  for (Message& m : b.messageLog().messages())
    if (m.level == level) result.push_back(std::move(m));
  return result;
}

TEST(Topology, NbPointsFromPositionsOrLargestIndex) {
  PlainTopology t;
  EXPECT_EQ(t.nbPoints(), 0u);
  t.d_tetrahedra.setValue(cubeInSixTetrahedra());
  EXPECT_EQ(t.nbPoints(), 8u);
  t.d_edges.setValue({{3, 41}});
  EXPECT_EQ(t.nbPoints(), 42u);
  t.d_position.setValue(unitCubePoints());
  EXPECT_EQ(t.nbPoints(), 8u);
}

TEST(Topology, AdjacencyIsCachedUntilTheElementsChange) {
  PlainTopology t;
  t.d_position.setValue(unitCubePoints());
  t.d_tetrahedra.setValue(cubeInSixTetrahedra());
  const std::uint64_t r0 = t.revision();
  const std::vector<Triangle>* first = &t.boundaryTriangles();
  EXPECT_EQ(first->size(), 12u);
  EXPECT_EQ(&t.boundaryTriangles(), first);  // the same cached object
  EXPECT_EQ(t.revision(), r0);

  // Moving the points keeps the adjacency and the revision.
  t.d_position.edit()[0] = Vec3d(-0.1, 0, 0);
  EXPECT_EQ(t.revision(), r0);
  EXPECT_EQ(t.tetrahedraAroundVertex()[0].size(), 6u);

  // New elements: new revision, recomputed adjacency.
  t.d_tetrahedra.setValue(cubeInFiveTetrahedra());
  EXPECT_GT(t.revision(), r0);
  EXPECT_EQ(t.tetrahedronFaces().faces.size(), 16u);
  EXPECT_EQ(t.tetrahedraAroundVertex()[0].size(), 4u);
  EXPECT_EQ(t.tetrahedronEdges().edges.size(), 18u);
}

TEST(Topology, RevisionFollowsLinkedData) {
  PlainTopology source, follower;
  source.d_tetrahedra.setValue(cubeInSixTetrahedra());
  std::string why;
  ASSERT_TRUE(follower.d_tetrahedra.setParent(&source.d_tetrahedra, why)) << why;
  const std::uint64_t r0 = follower.revision();
  EXPECT_EQ(follower.boundaryTriangles().size(), 12u);
  source.d_tetrahedra.setValue(cubeInFiveTetrahedra());
  EXPECT_GT(follower.revision(), r0);
  EXPECT_EQ(follower.tetrahedronFaces().faces.size(), 16u);
}

TEST(Topology, HexahedraAdjacencyAndAllEdges) {
  const HexGrid grid = hexGrid(2);
  PlainTopology t;
  t.d_position.setValue(grid.points);
  t.d_hexahedra.setValue(grid.hexahedra);
  EXPECT_EQ(t.boundaryQuads().size(), 24u);
  EXPECT_EQ(t.hexahedronFaces().faces.size(), 36u);
  EXPECT_EQ(t.allEdges().size(), 54u);
  EXPECT_EQ(t.edgesAroundVertex()[13].size(), 6u);
  EXPECT_EQ(t.hexahedraAroundVertex()[13].size(), 8u);
  EXPECT_EQ(t.hexahedronEdges().edgesInElement.size(), 8u);
  EXPECT_TRUE(t.check());
}

TEST(Topology, CheckReportsIndicesOutOfRangeWithTheField) {
  PlainTopology t;
  t.d_position.setValue(unitCubePoints());
  t.d_tetrahedra.setValue({{0, 1, 3, 4}, {0, 1, 3, 8}});
  t.d_triangles.setValue({{0, 1, 12}});
  EXPECT_FALSE(t.check());
  const auto errors = messagesOf(t, MessageLevel::error);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].field, "triangles");
  EXPECT_NE(errors[0].text.find("triangle 0 (0 1 12)"), std::string::npos) << errors[0].text;
  EXPECT_EQ(errors[1].field, "tetrahedra");
  EXPECT_NE(errors[1].text.find("tetrahedron 1 (0 1 3 8)"), std::string::npos) << errors[1].text;
  EXPECT_NE(errors[1].text.find("8 points"), std::string::npos) << errors[1].text;
}

TEST(Topology, CheckReportsDegenerateAsErrorAndInvertedAsWarning) {
  PlainTopology t;
  t.d_position.setValue(unitCubePoints());
  t.d_tetrahedra.setValue({{0, 1, 3, 4}, {0, 3, 1, 4}, {0, 1, 2, 3}});
  EXPECT_FALSE(t.check());
  const auto errors = messagesOf(t, MessageLevel::error);
  const auto warnings = messagesOf(t, MessageLevel::warning);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].text.find("1 degenerate tetrahedron"), std::string::npos) << errors[0].text;
  EXPECT_NE(errors[0].text.find("tetrahedron 2 (0 1 2 3)"), std::string::npos) << errors[0].text;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].text.find("1 inverted tetrahedron"), std::string::npos) << warnings[0].text;
  EXPECT_NE(warnings[0].text.find("tetrahedron 1 (0 3 1 4)"), std::string::npos)
      << warnings[0].text;
  EXPECT_EQ(warnings[0].field, "tetrahedra");
}

TEST(Topology, ManyBadElementsAreListedShortly) {
  PlainTopology t;
  t.d_position.setValue(unitCubePoints());
  std::vector<Tetrahedron> inverted(25, Tetrahedron{0, 3, 1, 4});
  t.d_tetrahedra.setValue(inverted);
  EXPECT_TRUE(t.check());
  const auto warnings = messagesOf(t, MessageLevel::warning);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].text.find("25 inverted"), std::string::npos);
  EXPECT_NE(warnings[0].text.find("and 15 more"), std::string::npos) << warnings[0].text;
}

TEST(Topology, NoPositionsNoGeometricChecks) {
  PlainTopology t;
  t.d_tetrahedra.setValue({{0, 1, 2, 2}});
  EXPECT_TRUE(t.check());
}

}  // namespace
}  // namespace stroma::test
