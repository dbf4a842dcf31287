// SPDX-License-Identifier: MIT
// SphereROI: exactly the grid points within the spheres (|p - c| <= r, compared with a direct
// count), elements inside when all their points are in one same sphere, the edge-direction
// filter, PlaneROI (BoxROI's oriented box) selecting exactly a slab, and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "plugins/Spring/MechanicsTestSupport.h"

namespace stroma::test {
namespace {

// A 5 x 5 x 5 grid of unit spacing on [0, 4]^3 and an engine.
std::string gridScene(const std::string& engine) {
  return R"(
<Node name="root" gravity="0 0 0">
  <Node name="body">
    <RegularGridTopology name="grid" n="5 5 5" min="0 0 0" max="4 4 4"/>
    <MechanicalObject name="dofs" position="@grid.position"/>
    )" + engine + R"(
  </Node>
</Node>)";
}

std::vector<unsigned> unsignedList(const std::string& text) {
  std::vector<unsigned> v;
  for (double x : numbers(text)) v.push_back(static_cast<unsigned>(x));
  return v;
}

TEST(SphereROI, SelectsExactlyThePointsWithinTheSpheres) {
  SceneHolder s;
  // Radius 1.5 about a grid point: its 6 neighbours at 1, 12 at sqrt(2) = 1.41, not the 8 at
  // sqrt(3) = 1.73; one radius for both centers.
  ASSERT_TRUE(s.load(gridScene(
      R"(<SphereROI name="roi" centers="2 2 2  0 0 0" radii="1.5" computeEdges="0"/>)")));
  const auto x = numbers(s.text("@body/dofs.position"));
  std::vector<unsigned> expected;
  for (std::size_t i = 0; i < x.size() / 3; ++i) {
    const Vec3d p(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
    if ((p - Vec3d(2, 2, 2)).norm() <= 1.5 || p.norm() <= 1.5)
      expected.push_back(static_cast<unsigned>(i));
  }
  EXPECT_EQ(expected.size(), 19u + 7u);  // 1 + 6 + 12 about (2,2,2); the corner's octant: 1 + 3 + 3
  EXPECT_EQ(unsignedList(s.text("@body/roi.indices")), expected);
  EXPECT_EQ(s.text("@body/roi.nbIndices"), "26");
}

TEST(SphereROI, ElementsInsideOneSphereAndAlongADirection) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  10 0 0  11 0 0"/>
  <SphereROI name="roi" centers="0 0 0  10 0 0" radii="1.01 1.01"
             edges="0 1  0 2  1 3  3 4" triangles="0 1 2  1 3 4" tetrahedra="0 1 2 3"/>
  <SphereROI name="along" centers="0 0 0" radii="2" edges="0 1  0 2" direction="1 0.1 0"
             edgeAngle="10"/>
</Node>)"));
  EXPECT_EQ(s.text("@roi.indices"), "0 1 2 3 4");
  EXPECT_EQ(s.text("@roi.edgeIndices"), "0 1 3");  // 1-3 spans the two spheres: out
  EXPECT_EQ(s.text("@roi.triangleIndices"), "0");
  EXPECT_EQ(s.text("@roi.tetrahedronIndices"), "");
  EXPECT_EQ(s.text("@along.edgeIndices"), "0");  // 0-2 is 84 degrees off the direction
}

TEST(SphereROI, ARadiusCountThatFitsNoCenterIsAnError) {
  SceneHolder s;
  s.loadFailing(R"(<Node name="root"><MechanicalObject position="0 0 0"/>
  <SphereROI centers="0 0 1  0 0 0" radii="0.1 0.2 0.3"/></Node>)",
                {"2 centers and 3 radii"});
}

TEST(PlaneROI, SelectsExactlyTheSlabAboutTheParallelogram) {
  SceneHolder s;
  // The square x, y in [0, 4] at z = 2 (p0 = (0 0 2), p1 = (4 0 2), p2 = (4 4 2)... SOFA's
  // parallelogram p0, p1, p2, p0 + p2 - p1), depth 2.2: the layers z = 1, 2, 3.
  ASSERT_TRUE(s.load(gridScene(R"(<PlaneROI name="roi" plane="0 0 2  4 0 2  4 4 2  2.2"/>)")));
  const auto x = numbers(s.text("@body/dofs.position"));
  std::vector<unsigned> expected;
  for (std::size_t i = 0; i < x.size() / 3; ++i)
    if (std::abs(x[3 * i + 2] - 2) <= 1.1) expected.push_back(static_cast<unsigned>(i));
  EXPECT_EQ(expected.size(), 75u);
  EXPECT_EQ(unsignedList(s.text("@body/roi.indices")), expected);
  // The hexahedra of the two cell layers between z = 1 and z = 3.
  EXPECT_EQ(unsignedList(s.text("@body/roi.hexahedronIndices")).size(), 32u);
}

}  // namespace
}  // namespace stroma::test
