// SPDX-License-Identifier: MIT
#include "ScenePicker.h"

#include <gtest/gtest.h>

#include "core/Runtime.h"
#include "simulation/Scene.h"

namespace stroma::viewer {
namespace {

TEST(ScenePicker, ARayMeetsATriangleInsideAndMissesOutside) {
  const Vec3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const auto s = intersectTriangle(Vec3d(0.25, 0.25, 2), -Vec3d::UnitZ(), a, b, c);
  ASSERT_TRUE(s.has_value());
  EXPECT_DOUBLE_EQ(*s, 2.0);
  // The back face counts too; outside, parallel, or behind the origin does not.
  EXPECT_TRUE(intersectTriangle(Vec3d(0.25, 0.25, -1), Vec3d::UnitZ(), a, b, c).has_value());
  EXPECT_FALSE(intersectTriangle(Vec3d(0.75, 0.75, 2), -Vec3d::UnitZ(), a, b, c).has_value());
  EXPECT_FALSE(intersectTriangle(Vec3d(0.25, 0.25, 2), Vec3d::UnitX(), a, b, c).has_value());
  EXPECT_FALSE(intersectTriangle(Vec3d(0.25, 0.25, 2), Vec3d::UnitZ(), a, b, c).has_value());
}

class ScenePickerScene : public ::testing::Test {
 protected:
  Runtime runtime;
  Scene scene{runtime};
};

// Two tetrahedra's surface (a box cut in two would do as well): the surface is the outer faces
// of the tetrahedra, and the first one met along the ray wins.
TEST_F(ScenePickerScene, PicksTheNearestVertexOfTheFirstSurfaceTriangleMet) {
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
    <Node name="Body">
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  0 0 -1"/>
      <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 3  0 2 1 4"/>
    </Node>
  </Node>)")) << scene.log().errorCount();
  const auto surfaces = collectPickSurfaces(scene.root());
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_EQ(surfaces[0].triangles.size(), 6u);  // 8 faces, the shared one inside
  // From above (+z), near point 3's corner of the slanted face: point 3 is the nearest vertex.
  const auto picked = pickAlongRay(surfaces, Vec3d(0.1, 0.1, 5), -Vec3d::UnitZ(), 0.01);
  ASSERT_TRUE(picked.has_value());
  EXPECT_EQ(picked->index, 3u);
  EXPECT_NEAR(picked->hit.z(), 0.8, 1e-12);  // on x + y + z = 1
  EXPECT_NEAR(picked->rayDistance, 4.2, 1e-12);
  // From below, the lower tetrahedron's face toward point 4.
  const auto below = pickAlongRay(surfaces, Vec3d(0.1, 0.1, -5), Vec3d::UnitZ(), 0.01);
  ASSERT_TRUE(below.has_value());
  EXPECT_EQ(below->index, 4u);
  EXPECT_FALSE(pickAlongRay(surfaces, Vec3d(2, 2, 5), -Vec3d::UnitZ(), 0.01).has_value());
}

TEST_F(ScenePickerScene, PointsWithoutTrianglesArePickedWithinTheCone) {
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  1 0.05 -1"/>
  </Node>)"));
  const auto surfaces = collectPickSurfaces(scene.root());
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_TRUE(surfaces[0].triangles.empty());
  // Toward point 1 from 10 away, slightly off: 0.02 off the axis at distance 10 is inside a
  // cone of 0.01 per unit of distance (0.1 there). Point 2 is farther from the axis relative to
  // its cone, so point 1 wins.
  const Vec3d origin(1.02, 0, 10);
  const auto picked = pickAlongRay(surfaces, origin, -Vec3d::UnitZ(), 0.01);
  ASSERT_TRUE(picked.has_value());
  EXPECT_EQ(picked->index, 1u);
  // A narrower cone (0.001 per unit: 0.01 at point 1) leaves every point out.
  EXPECT_FALSE(pickAlongRay(surfaces, origin, -Vec3d::UnitZ(), 0.001).has_value());
}

}  // namespace
}  // namespace stroma::viewer
