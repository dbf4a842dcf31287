// SPDX-License-Identifier: MIT
// The Topology plugin's components in small inline scenes: containers (with SOFA's other
// attribute names, src="@loader", filename), the checks they report, RegularGridTopology, and
// the topological mappings.
#include <gtest/gtest.h>

#include "plugins/MeshIO/SceneFixture.h"
#include "topology/MeshGeometry.h"

namespace stroma::test {
namespace {

using TopologyTest = SceneFixture;

std::string wrap(const std::string& body) { return "<Node name=\"root\">\n" + body + "</Node>\n"; }

const char* kCubePoints = "0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1";
const char* kCubeTetrahedra = "1 0 5 2  3 0 2 7  4 0 7 5  6 2 5 7  0 2 7 5";

double totalVolume(const Topology& t) {
  double v = 0;
  for (const Tetrahedron& tet : t.tetrahedra()) v += signedVolume(t.positions(), tet);
  return v;
}

// --- Containers ---------------------------------------------------------------------------------

TEST_F(TopologyTest, MeshTopologyKeepsElementsAsGivenUnderEitherName) {
  ASSERT_TRUE(load(wrap(std::string("<MeshTopology name=\"a\" position=\"") + kCubePoints +
                        "\" tetrahedra=\"" + kCubeTetrahedra +
                        "\" edges=\"0 1\"/>\n"
                        "<MeshTopology name=\"b\" points=\"" +
                        kCubePoints + "\" tetras=\"" + kCubeTetrahedra +
                        "\" lines=\"0 1\" hexas=\"0 1 2 3 4 5 6 7\"/>\n")))
      << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  const Topology* a = topology("/a");
  const Topology* b = topology("/b");
  EXPECT_EQ(a->nbPoints(), 8u);
  EXPECT_EQ(a->edges().size(), 1u);     // kept as given: no edges added
  EXPECT_TRUE(a->triangles().empty());  // nor faces
  EXPECT_EQ(b->positions(), a->positions());
  EXPECT_EQ(b->tetrahedra(), a->tetrahedra());
  EXPECT_EQ(b->edges(), a->edges());
  EXPECT_EQ(b->hexahedra().size(), 1u);
  // The adjacency is there on demand.
  EXPECT_EQ(a->boundaryTriangles().size(), 12u);
  EXPECT_EQ(a->allEdges().size(), 18u);
}

TEST_F(TopologyTest, SetContainersCreateTheirSubElements) {
  ASSERT_TRUE(load(
      wrap(std::string("<TetrahedronSetTopologyContainer name=\"tets\" position=\"") + kCubePoints +
           "\" tetrahedra=\"" + kCubeTetrahedra +
           "\"/>\n"
           "<TetrahedronSetTopologyModifier/>\n<TetrahedronSetGeometryAlgorithms template=\"Vec3\" "
           "drawTetrahedra=\"1\" drawColorTetrahedra=\"1 0 0 1\"/>\n"
           "<HexahedronSetTopologyContainer name=\"hexas\" hexas=\"0 1 2 3 4 5 6 7\"/>\n"
           "<TriangleSetTopologyContainer name=\"tris\" triangles=\"0 1 2 0 2 3\"/>\n"
           "<QuadSetTopologyContainer name=\"quads\" quads=\"0 1 2 3\"/>\n"
           "<EdgeSetTopologyContainer name=\"edges\" edges=\"0 1 1 2\"/>\n"
           "<PointSetTopologyContainer name=\"points\" position=\"0 0 0 1 1 1\"/>\n")))
      << messages();
  const Topology* tets = topology("/tets");
  EXPECT_EQ(tets->triangles().size(), 16u);
  EXPECT_EQ(tets->edges().size(), 18u);
  const Topology* hexas = topology("/hexas");
  EXPECT_EQ(hexas->quads().size(), 6u);
  EXPECT_EQ(hexas->edges().size(), 12u);
  EXPECT_EQ(topology("/tris")->edges().size(), 5u);
  EXPECT_EQ(topology("/quads")->edges().size(), 4u);
  EXPECT_EQ(topology("/edges")->edges().size(), 2u);
  EXPECT_EQ(topology("/points")->nbPoints(), 2u);
}

TEST_F(TopologyTest, ContainersTakeFromLoadersWhatTheyKeep) {
  ASSERT_TRUE(load(wrap("<MeshGmshLoader name=\"loader\" filename=\"" + data("cube_v22.msh") +
                        "\"/>\n"
                        "<TetrahedronSetTopologyContainer name=\"tets\" src=\"@loader\"/>\n"
                        "<HexahedronSetTopologyContainer name=\"hexas\" src=\"@loader\"/>\n"
                        "<MeshTopology name=\"all\" src=\"@loader\"/>\n")))
      << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  const Topology* tets = topology("/tets");
  EXPECT_EQ(tets->tetrahedra().size(), 5u);
  EXPECT_TRUE(tets->hexahedra().empty());   // a tetrahedron set keeps no hexahedra
  EXPECT_EQ(tets->triangles().size(), 2u);  // the loader's two triangles, kept as given
  EXPECT_EQ(tets->edges().size(), 1u);
  const Topology* hexas = topology("/hexas");
  EXPECT_EQ(hexas->hexahedra().size(), 1u);
  EXPECT_TRUE(hexas->tetrahedra().empty());
  EXPECT_TRUE(hexas->triangles().empty());
  EXPECT_EQ(hexas->quads().size(), 6u);
  const Topology* all = topology("/all");
  EXPECT_EQ(all->tetrahedra().size(), 5u);
  EXPECT_EQ(all->hexahedra().size(), 1u);
}

TEST_F(TopologyTest, ElementsTheContainerDoesNotKeepAreAWarning) {
  ASSERT_TRUE(
      load(wrap(std::string("<TriangleSetTopologyContainer name=\"t\" position=\"") + kCubePoints +
                "\" triangles=\"0 1 2\" tetrahedra=\"" + kCubeTetrahedra + "\"/>\n")))
      << messages();
  const Message m = find(MessageLevel::warning, "5 tetrahedra ignored");
  EXPECT_EQ(m.field, "tetrahedra");
  EXPECT_TRUE(topology("/t")->tetrahedra().empty());
}

TEST_F(TopologyTest, FilenameReadsTheMesh) {
  ASSERT_TRUE(load(wrap("<MeshTopology name=\"m\" filename=\"" + data("cube.obj") +
                        "\"/>\n"
                        "<TetrahedronSetTopologyContainer name=\"t\" fileTopology=\"" +
                        data("cube_v41.msh") + "\"/>\n")))
      << messages();
  EXPECT_EQ(topology("/m")->quads().size(), 5u);
  EXPECT_EQ(topology("/t")->tetrahedra().size(), 5u);
  EXPECT_EQ(topology("/t")->nbPoints(), 8u);
}

TEST_F(TopologyTest, BadFilenameIsAnError) {
  const std::string bad = write("bad.obj", "v 0 0 0\nf 1 2 3\n");
  EXPECT_FALSE(load(wrap("<MeshTopology name=\"m\" filename=\"" + bad + "\"/>\n")));
  const Message m = find(MessageLevel::error, "vertex index 2 is out of range");
  EXPECT_EQ(m.field, "filename");
  EXPECT_NE(m.text.find("line 2"), std::string::npos);
}

TEST_F(TopologyTest, IndicesOutOfRangeAreErrorsNamingFieldAndElement) {
  EXPECT_FALSE(load(wrap(std::string("<TetrahedronSetTopologyContainer name=\"t\" position=\"") +
                         kCubePoints + "\" tetrahedra=\"0 1 3 4  0 1 3 8\"/>\n")));
  const Message m = find(MessageLevel::error, "out of range");
  EXPECT_EQ(m.field, "tetrahedra");
  EXPECT_EQ(m.componentPath, "/root/t");
  EXPECT_EQ(m.where.line, 2);
  EXPECT_NE(m.text.find("tetrahedron 1 (0 1 3 8)"), std::string::npos) << m.text;
}

TEST_F(TopologyTest, DegenerateIsAnErrorInvertedAWarning) {
  EXPECT_FALSE(
      load(wrap(std::string("<MeshTopology name=\"t\" position=\"") + kCubePoints +
                "\" tetrahedra=\"0 1 3 4  0 3 1 4  0 1 2 3\" hexahedra=\"4 5 6 7 0 1 2 3\"/>\n")));
  EXPECT_NE(find(MessageLevel::error, "1 degenerate tetrahedron").text.find("tetrahedron 2"),
            std::string::npos);
  EXPECT_NE(find(MessageLevel::warning, "1 inverted tetrahedron").text.find("tetrahedron 1"),
            std::string::npos);
  EXPECT_EQ(find(MessageLevel::warning, "1 inverted hexahedron").field, "hexahedra");
}

// --- RegularGridTopology ------------------------------------------------------------------------

TEST_F(TopologyTest, RegularGridNumberingAndCounts) {
  ASSERT_TRUE(
      load(wrap("<RegularGridTopology name=\"g\" n=\"3 4 5\" min=\"0 0 0\" max=\"2 3 8\"/>\n"
                "<RegularGridTopology name=\"noTriangles\" nx=\"3\" ny=\"3\" nz=\"3\" "
                "computeTriangleList=\"false\"/>\n")))
      << messages();
  const Topology* g = topology("/g");
  ASSERT_EQ(g->nbPoints(), 60u);
  EXPECT_EQ(g->positions()[1], Vec3d(1, 0, 0));
  EXPECT_EQ(g->positions()[3], Vec3d(0, 1, 0));
  EXPECT_EQ(g->positions()[12], Vec3d(0, 0, 2));
  EXPECT_EQ(g->positions()[59], Vec3d(2, 3, 8));
  ASSERT_EQ(g->hexahedra().size(), 2u * 3u * 4u);
  EXPECT_EQ(g->hexahedra()[0], (Hexahedron{0, 1, 4, 3, 12, 13, 16, 15}));
  EXPECT_EQ(g->quads().size(), 2u * 3u * 5u + 2u * 4u * 4u + 3u * 3u * 4u);
  EXPECT_EQ(g->triangles().size(), 2 * g->quads().size());  // SOFA's default
  EXPECT_TRUE(checkHexahedra(g->positions(), g->hexahedra()).empty());
  const Topology* plain = topology("/noTriangles");
  EXPECT_EQ(plain->nbPoints(), 27u);
  EXPECT_TRUE(plain->triangles().empty());
  EXPECT_EQ(plain->edges().size(), 54u);              // the grid segments
  EXPECT_EQ(plain->positions()[26], Vec3d(1, 1, 1));  // default min 0 0 0, max 1 1 1
}

TEST_F(TopologyTest, RegularGridExtentSettings) {
  ASSERT_TRUE(load(wrap(
      "<RegularGridTopology name=\"a\" nx=\"2\" ny=\"2\" nz=\"2\" xmin=\"-1\" xmax=\"1\" "
      "ymin=\"0\" "
      "ymax=\"5\" zmin=\"2\" zmax=\"3\"/>\n"
      "<RegularGridTopology name=\"b\" n=\"2 2 2\" min=\"0 0 0\" max=\"1 1 2.7\" p0=\"4 0 0\"/>\n"
      "<RegularGridTopology name=\"c\" n=\"1 3 1\" min=\"0 0 0\" max=\"2 2 2\"/>\n"
      "<RegularGridTopology name=\"d\" cellWidth=\"0.5\" min=\"0 0 0\" max=\"1 1 2\"/>\n")))
      << messages();
  EXPECT_EQ(topology("/a")->positions().front(), Vec3d(-1, 0, 2));
  EXPECT_EQ(topology("/a")->positions().back(), Vec3d(1, 5, 3));
  EXPECT_EQ(topology("/b")->positions().front(), Vec3d(4, 0, 0));
  EXPECT_EQ(topology("/b")->positions().back(), Vec3d(5, 1, 2.7));
  // One point along x and z: x in the middle, z at min (as SOFA).
  EXPECT_EQ(topology("/c")->positions(),
            (std::vector<Vec3d>{Vec3d(1, 0, 0), Vec3d(1, 1, 0), Vec3d(1, 2, 0)}));
  EXPECT_TRUE(topology("/c")->hexahedra().empty());
  EXPECT_EQ(topology("/d")->nbPoints(), 3u * 3u * 5u);
}

TEST_F(TopologyTest, RegularGridPointsAreThereBeforeItsInit) {
  // The mechanical state comes first and links the grid's points.
  ASSERT_TRUE(
      load(wrap("<MechanicalObject name=\"dofs\" position=\"@grid.position\"/>\n"
                "<RegularGridTopology name=\"grid\" n=\"2 2 3\"/>\n")))
      << messages();
  EXPECT_EQ(value("/dofs", "position"), value("/grid", "position"));
  EXPECT_EQ(value("/dofs", "size"), "0");
  EXPECT_FALSE(value("/dofs", "position").empty());
}

TEST_F(TopologyTest, RegularGridTooLargeIsAnError) {
  EXPECT_FALSE(load(wrap("<RegularGridTopology name=\"g\" n=\"1000 1000 1000\"/>\n")));
  EXPECT_EQ(find(MessageLevel::error, "larger than the 10^7 points").field, "n");
}

// --- Topological mappings -----------------------------------------------------------------------

TEST_F(TopologyTest, Hexa2TetraSplitsTheGridIntoPositiveTetrahedra) {
  ASSERT_TRUE(load(
      wrap("<Node name=\"six\">\n"
           "  <RegularGridTopology name=\"grid\" n=\"4 3 3\" min=\"-1 0 0\" max=\"2 2 1\"/>\n"
           "  <TetrahedronSetTopologyContainer name=\"tets\" position=\"@grid.position\"/>\n"
           "  <TetrahedronSetTopologyModifier/>\n"
           "  <Hexa2TetraTopologicalMapping input=\"@grid\" output=\"@tets\"/>\n"
           "</Node>\n"
           "<Node name=\"swapped\">\n"
           "  <RegularGridTopology name=\"grid\" n=\"4 3 3\" min=\"-1 0 0\" max=\"2 2 1\"/>\n"
           "  <HexahedronSetTopologyContainer name=\"hexas\" src=\"@grid\"/>\n"
           "  <Node name=\"tetras\">\n"
           "    <TetrahedronSetTopologyContainer name=\"tets\"/>\n"
           "    <Hexa2TetraTopologicalMapping input=\"@../\" output=\"@tets\" swapping=\"true\"/>\n"
           "  </Node>\n"
           "</Node>\n"
           "<Node name=\"five\">\n"
           "  <RegularGridTopology name=\"grid\" n=\"4 3 3\" min=\"-1 0 0\" max=\"2 2 1\"/>\n"
           "  <TetrahedronSetTopologyContainer name=\"tets\"/>\n"
           "  <Hexa2TetraTopologicalMapping input=\"@grid\" output=\"@tets\" "
           "tetrahedraPerHexahedron=\"5\"/>\n"
           "</Node>\n"
           "<Node name=\"follower\">\n"
           "  <TetrahedronSetTopologyContainer name=\"tets\" src=\"@../six/tets\"/>\n"
           "</Node>\n")))
      << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  // 3 x 2 x 2 = 12 hexahedra, volume 3 x 2 x 1.
  for (const char* path : {"/six/tets", "/swapped/tetras/tets", "/five/tets", "/follower/tets"}) {
    const Topology* t = topology(path);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->tetrahedra().size(), std::string(path) == "/five/tets" ? 60u : 72u) << path;
    EXPECT_NEAR(totalVolume(*t), 6.0, 1e-12) << path;
    EXPECT_TRUE(checkTetrahedra(t->positions(), t->tetrahedra()).empty()) << path;
    // Conforming: two boundary triangles per boundary quad of the grid (16 + 24 + 24 = 32... ).
    EXPECT_EQ(t->boundaryTriangles().size(), 2u * (2 * 3 * 2 + 2 * 3 * 2 + 2 * 2 * 2)) << path;
    EXPECT_EQ(t->triangles().size(), t->tetrahedronFaces().faces.size()) << path;
  }
  EXPECT_NE(value("/six/tets", "tetrahedra"), value("/swapped/tetras/tets", "tetrahedra"));
  EXPECT_EQ(value("/follower/tets", "tetrahedra"), value("/six/tets", "tetrahedra"));
}

TEST_F(TopologyTest, Hexa2TetraSwappingNeedsAGrid) {
  ASSERT_TRUE(load(
      wrap(std::string("<MeshTopology name=\"hexas\" position=\"") + kCubePoints +
           " 2 0 0  2 1 0  2 0 1  2 1 1\" hexahedra=\"1 8 9 2 5 10 11 6  0 1 2 3 4 5 6 7\"/>\n"
           "<TetrahedronSetTopologyContainer name=\"tets\"/>\n"
           "<Hexa2TetraTopologicalMapping input=\"@hexas\" output=\"@tets\" swapping=\"1\"/>\n")))
      << messages();
  EXPECT_EQ(find(MessageLevel::warning, "numbered as a regular grid").field, "swapping");
  EXPECT_EQ(topology("/tets")->tetrahedra().size(), 12u);
  EXPECT_NEAR(totalVolume(*topology("/tets")), 2.0, 1e-12);
}

TEST_F(TopologyTest, Hexa2QuadGivesTheOutwardBoundary) {
  ASSERT_TRUE(
      load(wrap("<RegularGridTopology name=\"grid\" n=\"3 3 3\"/>\n"
                "<Node name=\"surface\">\n"
                "  <QuadSetTopologyContainer name=\"quads\"/>\n"
                "  <QuadSetTopologyModifier/>\n"
                "  <Hexa2QuadTopologicalMapping input=\"@../grid\" output=\"@quads\"/>\n"
                "</Node>\n")))
      << messages();
  const Topology* q = topology("/surface/quads");
  ASSERT_EQ(q->quads().size(), 24u);
  EXPECT_EQ(q->nbPoints(), 27u);  // the grid's points, given to the output
  for (const Quad& quad : q->quads()) {
    const auto& p = q->positions();
    const Vec3d n = (p[quad[1]] - p[quad[0]]).cross(p[quad[3]] - p[quad[0]]);
    const Vec3d c = (p[quad[0]] + p[quad[1]] + p[quad[2]] + p[quad[3]]) / 4;
    EXPECT_GT(n.dot(c - Vec3d(0.5, 0.5, 0.5)), 0);
  }
}

TEST_F(TopologyTest, Tetra2TriangleGivesTheOutwardBoundary) {
  ASSERT_TRUE(load(wrap(
      std::string("<TetrahedronSetTopologyContainer name=\"volume\" position=\"") + kCubePoints +
      "\" tetrahedra=\"" + kCubeTetrahedra +
      "\"/>\n"
      "<Node name=\"out\">\n"
      "  <TriangleSetTopologyContainer name=\"c\"/>\n"
      "  <Tetra2TriangleTopologicalMapping input=\"@../volume\" output=\"@c\"/>\n"
      "</Node>\n"
      "<Node name=\"in\">\n"
      "  <TriangleSetTopologyContainer name=\"c\"/>\n"
      "  <Tetra2TriangleTopologicalMapping input=\"@../volume\" output=\"@c\" flipNormals=\"1\"/>\n"
      "</Node>\n"
      "<Node name=\"none\">\n"
      "  <TriangleSetTopologyContainer name=\"c\"/>\n"
      "  <Tetra2TriangleTopologicalMapping input=\"@../volume\" output=\"@c\" "
      "noInitialTriangles=\"1\"/>\n"
      "</Node>\n")))
      << messages();
  auto outwardCount = [&](const char* path) {
    const Topology* t = topology(path);
    int outward = 0;
    for (const Triangle& tri : t->triangles()) {
      const auto& p = t->positions();
      const Vec3d n = (p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]);
      if (n.dot((p[tri[0]] + p[tri[1]] + p[tri[2]]) / 3 - Vec3d(0.5, 0.5, 0.5)) > 0) ++outward;
    }
    return outward;
  };
  EXPECT_EQ(topology("/out/c")->triangles().size(), 12u);
  EXPECT_EQ(outwardCount("/out/c"), 12);
  EXPECT_EQ(outwardCount("/in/c"), 0);
  EXPECT_EQ(topology("/out/c")->edges().size(), 18u);
  EXPECT_TRUE(topology("/none/c")->triangles().empty());
}

TEST_F(TopologyTest, Quad2TriangleAndTriangle2Edge) {
  ASSERT_TRUE(
      load(wrap("<QuadSetTopologyContainer name=\"quads\" position=\"0 0 0 1 0 0 1 1 0 0 1 0\" "
                "quads=\"0 1 2 3\"/>\n"
                "<Node name=\"t\">\n"
                "  <TriangleSetTopologyContainer name=\"c\"/>\n"
                "  <Quad2TriangleTopologicalMapping input=\"@../quads\" output=\"@c\"/>\n"
                "  <Node name=\"e\">\n"
                "    <EdgeSetTopologyContainer name=\"c\"/>\n"
                "    <Triangle2EdgeTopologicalMapping input=\"@../c\" output=\"@c\"/>\n"
                "  </Node>\n"
                "</Node>\n")))
      << messages();
  EXPECT_EQ(value("/t/c", "triangles"), "0 1 2 0 2 3");
  EXPECT_EQ(topology("/t/e/c")->edges().size(), 4u);
}

TEST_F(TopologyTest, MappingToTheWrongKindOfContainerIsAnError) {
  EXPECT_FALSE(
      load(wrap("<RegularGridTopology name=\"grid\" n=\"2 2 2\"/>\n"
                "<TriangleSetTopologyContainer name=\"tris\"/>\n"
                "<Hexa2TetraTopologicalMapping input=\"@grid\" output=\"@tris\"/>\n"
                "<Tetra2TriangleTopologicalMapping output=\"@tris\"/>\n")));
  EXPECT_EQ(
      find(MessageLevel::error, "keeps no tetrahedra; expected a TetrahedronSetTopologyContainer")
          .field,
      "output");
  EXPECT_EQ(find(MessageLevel::error, "no input topology").field, "input");
}

}  // namespace
}  // namespace stroma::test
