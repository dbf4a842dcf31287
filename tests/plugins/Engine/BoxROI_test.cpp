// SPDX-License-Identifier: MIT
// BoxROI: the points and elements of a grid inside boxes, the default inputs (state, topology),
// lazy pulling by a constraint, changes of the box, and bad input.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"

namespace stroma::test {
namespace {

// A 4 x 4 x 4 grid of unit spacing on [0, 3]^3, its 27 hexahedra, and a box.
std::string gridScene(const std::string& boxAttributes) {
  return R"(
<Node name="root" gravity="0 0 0">
  <Node name="body">
    <RegularGridTopology name="grid" n="4 4 4" min="0 0 0" max="3 3 3"/>
    <MechanicalObject name="dofs" position="@grid.position"/>
    <BoxROI name="box" )" +
         boxAttributes + R"(/>
  </Node>
</Node>)";
}

/// Indices of the grid points with x, y, z in the given closed ranges.
std::vector<unsigned> expectedPoints(SceneHolder& s, const Vec6d& box) {
  const auto x = numbers(s.text("@body/dofs.position"));
  std::vector<unsigned> inside;
  for (std::size_t i = 0; i < x.size() / 3; ++i) {
    bool in = true;
    for (int d = 0; d < 3; ++d) in &= x[3 * i + d] >= box[d] && x[3 * i + d] <= box[d + 3];
    if (in) inside.push_back(static_cast<unsigned>(i));
  }
  return inside;
}

std::vector<unsigned> unsignedList(const std::string& text) {
  std::vector<unsigned> v;
  for (double x : numbers(text)) v.push_back(static_cast<unsigned>(x));
  return v;
}

TEST(BoxROI, PointsOfAGrid) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene(R"(box="0.5 -0.1 -0.1  2.5 3.1 1.1")")));
  const auto indices = unsignedList(s.text("@body/box.indices"));
  EXPECT_EQ(indices.size(), 2u * 4 * 2);
  EXPECT_EQ(indices, expectedPoints(s, (Vec6d() << 0.5, -0.1, -0.1, 2.5, 3.1, 1.1).finished()));
  EXPECT_EQ(s.text("@body/box.nbIndices"), "16");
  EXPECT_EQ(numbers(s.text("@body/box.pointsInROI")).size(), 16u * 3);
  EXPECT_EQ(unsignedList(s.text("@body/box.indicesOut")).size(), 64u - 16);
}

TEST(BoxROI, FacesAreInsideAndBoxesAddUp) {
  SceneHolder s;
  // The first box's faces pass through grid points; the second box adds the corner (3,3,3).
  ASSERT_TRUE(s.load(gridScene(R"(box="0 0 0 1 1 1   2.9 2.9 2.9 3 3 3")")));
  auto expected = expectedPoints(s, (Vec6d() << 0, 0, 0, 1, 1, 1).finished());
  expected.push_back(63);
  EXPECT_EQ(unsignedList(s.text("@body/box.indices")), expected);
}

TEST(BoxROI, ElementsInsideStrictlyOrByBarycentre) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene(R"(box="-0.1 -0.1 -0.1 3.1 3.1 1.5")")));
  // The default element lists are those of the node's topology: 9 hexahedra fully inside.
  EXPECT_EQ(unsignedList(s.text("@body/box.hexahedronIndices")).size(), 9u);
  EXPECT_EQ(numbers(s.text("@body/box.hexahedraInROI")).size(), 9u * 8);
  s.set("@body/box.strict", "0");  // barycentres at z = 0.5 and 1.5 are inside
  EXPECT_EQ(unsignedList(s.text("@body/box.hexahedronIndices")).size(), 18u);
}

TEST(BoxROI, GivenTetrahedraAndTriangles) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  5 5 5"/>
  <BoxROI name="box" box="-1 -1 -1 2 2 2" tetrahedra="0 1 2 3  1 2 3 4" triangles="0 1 2  2 3 4"
          edges="0 4  1 2"/>
</Node>)"));
  EXPECT_EQ(s.text("@box.indices"), "0 1 2 3");  // position from the state's rest positions
  EXPECT_EQ(s.text("@box.tetrahedronIndices"), "0");
  EXPECT_EQ(s.text("@box.tetrahedraInROI"), "0 1 2 3");
  EXPECT_EQ(s.text("@box.triangleIndices"), "0");
  EXPECT_EQ(s.text("@box.edgeIndices"), "1");
}

TEST(BoxROI, ConstraintPullsTheIndicesLazily) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 -10 0" dt="0.01">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>
  <Node name="body">
    <RegularGridTopology name="grid" n="3 3 3" min="0 0 0" max="2 2 2"/>
    <MechanicalObject name="dofs" position="@grid.position"/>
    <UniformMass vertexMass="1"/>
    <BoxROI name="box" box="-0.1 1.9 -0.1 2.1 2.1 2.1"/>
    <FixedProjectiveConstraint name="fixed" indices="@box.indices"/>
  </Node>
</Node>)"));
  const auto x0 = numbers(s.text("@body/dofs.position"));
  ASSERT_TRUE(s.step(5));
  const auto x = numbers(s.text("@body/dofs.position"));
  const auto fixed = unsignedList(s.text("@body/fixed.indices"));
  EXPECT_EQ(fixed.size(), 9u);
  for (std::size_t i = 0; i < x.size() / 3; ++i) {
    const bool isFixed = std::find(fixed.begin(), fixed.end(), i) != fixed.end();
    EXPECT_EQ(isFixed, x0[3 * i + 1] == 2) << i;
    if (isFixed)
      EXPECT_EQ(x[3 * i + 1], x0[3 * i + 1]);
    else
      EXPECT_LT(x[3 * i + 1], x0[3 * i + 1]);
  }
}

TEST(BoxROI, ChangingTheBoxUpdatesTheSelection) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene(R"(box="-0.1 -0.1 -0.1 0.1 0.1 0.1")")));
  EXPECT_EQ(s.text("@body/box.indices"), "0");
  s.set("@body/box.box", "2.9 2.9 2.9 3.1 3.1 3.1");
  EXPECT_EQ(s.text("@body/box.indices"), "63");
  SceneHolder t;  // doUpdate="0" keeps the first selection
  ASSERT_TRUE(t.load(gridScene(R"(box="-0.1 -0.1 -0.1 0.1 0.1 0.1" doUpdate="0")")));
  t.set("@body/box.box", "2.9 2.9 2.9 3.1 3.1 3.1");
  EXPECT_EQ(t.text("@body/box.indices"), "0");
}

TEST(BoxROI, OrientedBoxSelectsADiagonalBand) {
  // The parallelogram from corner (0.25, -0.25, 1) along (3, 3, 0) and (-0.5, 0.5, 0), 0.5
  // thick: the grid points with x = y at z = 1.
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene(R"(orientedBox="3.25 2.75 1  0.25 -0.25 1  -0.25 0.25 1  0.5")")));
  const auto x = numbers(s.text("@body/dofs.position"));
  std::vector<unsigned> expected;
  for (std::size_t i = 0; i < x.size() / 3; ++i)
    if (x[3 * i] == x[3 * i + 1] && x[3 * i + 2] == 1) expected.push_back(static_cast<unsigned>(i));
  ASSERT_EQ(expected.size(), 4u);
  EXPECT_EQ(unsignedList(s.text("@body/box.indices")), expected);
}

TEST(BoxROI, WithoutABoxTheUnitBoxIsUsed) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene(""), /*allowWarnings=*/true));
  EXPECT_EQ(unsignedList(s.text("@body/box.indices")),
            expectedPoints(s, (Vec6d() << 0, 0, 0, 1, 1, 1).finished()));
}

TEST(BoxROI, BadInputIsReported) {
  SceneHolder s;
  s.loadFailing(gridScene(R"(box="0 0 0 1 1")"), {"expected a multiple of 6 numbers"});
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(R"(<Node><MechanicalObject position="0 0 0  1 0 0"/>
<BoxROI box="-1 -1 -1 2 2 2" edges="0 1  1 5"/></Node>)",
                          {"1 elements use points out of range of the 2 positions", "element 1"})
                .field,
            "edges");
  SceneHolder u;
  EXPECT_EQ(u.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<BoxROI orientedBox="0 0 0 1 1 1 2 2 2 1"/></Node>)",
                          {"oriented box 0 is degenerate"})
                .field,
            "orientedBox");
}

TEST(BoxROI, PointsInAPlaneOrOnALineHaveTheirMissingCoordinatesZero) {
  // The BoxROI takes its template (Vec2d, Vec1d) from the node's state; a box selects the
  // points in the plane z = 0 (on the line y = z = 0) only when it contains that plane (line).
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(
<Node name="root" gravity="0 0 0">
  <Node name="plane">
    <RegularGridTopology name="grid" n="4 3 1" min="0 0 0" max="3 2 0"/>
    <MechanicalObject template="Vec2" name="dofs"/>
    <BoxROI name="inside" box="0.5 -0.1 -0.1  2.5 1.1 0.1"/>
    <BoxROI name="above" box="0.5 -0.1 0.5  2.5 1.1 1"/>
  </Node>
  <Node name="line">
    <RegularGridTopology name="grid" nx="5" ny="1" nz="1" xmin="0" xmax="4" ymin="0" ymax="0"
                         zmin="0" zmax="0"/>
    <MechanicalObject template="Vec1" name="dofs"/>
    <BoxROI name="inside" box="0.5 -1 -1  2.5 1 1"/>
    <BoxROI name="beside" box="0.5 0.5 -1  2.5 1 1"/>
  </Node>
</Node>)"));
  EXPECT_EQ(s.get<Base>("@plane/inside")->templateName(), "Vec2d");
  EXPECT_EQ(s.text("@plane/inside.position"), "0 0 1 0 2 0 3 0 0 1 1 1 2 1 3 1 0 2 1 2 2 2 3 2");
  EXPECT_EQ(s.text("@plane/inside.indices"), "1 2 5 6");
  EXPECT_EQ(s.text("@plane/inside.pointsInROI"), "1 0 2 0 1 1 2 1");
  EXPECT_EQ(s.text("@plane/inside.quadIndices"), "1");
  EXPECT_EQ(s.text("@plane/above.indices"), "");

  EXPECT_EQ(s.get<Base>("@line/inside")->templateName(), "Vec1d");
  EXPECT_EQ(s.text("@line/inside.position"), "0 1 2 3 4");
  EXPECT_EQ(s.text("@line/inside.indices"), "1 2");
  EXPECT_EQ(s.text("@line/inside.pointsOutROI"), "0 3 4");
  EXPECT_EQ(s.text("@line/inside.edgeIndices"), "1");
  EXPECT_EQ(s.text("@line/beside.indices"), "");
}

}  // namespace
}  // namespace stroma::test
