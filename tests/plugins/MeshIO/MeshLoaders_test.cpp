// SPDX-License-Identifier: MIT
// The loader components in scenes: outputs linked by other components, SOFA's post-processing
// options, and the errors a user sees (file, line, field).
#include <gtest/gtest.h>

#include "MeshWriters.h"
#include "plugins/MeshIO/SceneFixture.h"

namespace stroma::test {
namespace {

using LoaderTest = SceneFixture;

std::string wrap(const std::string& body) { return "<Node name=\"root\">\n" + body + "</Node>\n"; }

TEST_F(LoaderTest, EachLoaderFeedsATopology) {
  const std::string vtuBin = write("cube_bin.vtu", vtuBinary());
  const std::string stlBin = write("cube_bin.stl", stlBinary());
  const std::string mshBin = write("cube_bin.msh", gmsh41Binary());
  const std::string vtkBin = write("cube_bin.vtk", vtkLegacyBinary());
  ASSERT_TRUE(
      load(wrap("<MeshGmshLoader name=\"gmsh\" filename=\"" + data("cube_v22.msh") +
                "\"/>\n"
                "<MeshGmshLoader name=\"gmshBinary\" filename=\"" +
                mshBin +
                "\"/>\n"
                "<MeshVTKLoader name=\"vtk\" filename=\"" +
                data("cube_grid.vtk") +
                "\"/>\n"
                "<MeshVTKLoader name=\"vtkBinary\" filename=\"" +
                vtkBin +
                "\"/>\n"
                "<MeshVTKLoader name=\"vtu\" filename=\"" +
                data("cube.vtu") +
                "\"/>\n"
                "<MeshVTKLoader name=\"vtuBinary\" filename=\"" +
                vtuBin +
                "\"/>\n"
                "<MeshOBJLoader name=\"obj\" filename=\"" +
                data("cube.obj") +
                "\"/>\n"
                "<MeshSTLLoader name=\"stl\" filename=\"" +
                data("cube_ascii.stl") +
                "\"/>\n"
                "<MeshSTLLoader name=\"stlBinary\" filename=\"" +
                stlBin +
                "\"/>\n"
                "<Node name=\"a\"><MeshTopology name=\"t\" src=\"@../gmsh\"/></Node>\n"
                "<Node name=\"b\"><MeshTopology name=\"t\" src=\"@../vtuBinary\"/></Node>\n"
                "<Node name=\"c\"><MeshTopology name=\"t\" src=\"@../obj\"/></Node>\n"
                "<Node name=\"d\"><MeshTopology name=\"t\" src=\"@../stlBinary\"/></Node>\n")))
      << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  const Topology* gmsh = topology("/a/t");
  EXPECT_EQ(gmsh->nbPoints(), 8u);
  EXPECT_EQ(gmsh->tetrahedra(), cubeTetrahedra());
  EXPECT_EQ(gmsh->hexahedra().size(), 1u);
  EXPECT_EQ(gmsh->triangles().size(), 2u);
  EXPECT_EQ(topology("/b/t")->tetrahedra(), cubeTetrahedra());
  EXPECT_EQ(topology("/c/t")->quads().size(), 5u);
  EXPECT_EQ(topology("/d/t")->triangles().size(), 12u);
  for (const char* loader : {"/gmshBinary", "/vtk", "/vtkBinary", "/vtu"})
    EXPECT_EQ(value(loader, "tetrahedra"), value("/gmsh", "tetrahedra")) << loader;
  EXPECT_EQ(value("/stl", "triangles"), value("/stlBinary", "triangles"));
  EXPECT_FALSE(value("/obj", "texcoords").empty());
}

TEST_F(LoaderTest, TransformIsAppliedOnceAlthoughTheStateTakesSrc) {
  ASSERT_TRUE(load(wrap("<MeshGmshLoader name=\"loader\" filename=\"" + data("cube_v22.msh") +
                        "\" scale=\"2\" rotation=\"0 0 90\" translation=\"10 0 0\"/>\n"
                        "<MechanicalObject name=\"dofs\" src=\"@loader\"/>\n")))
      << messages();
  // Point 1 (1, 0, 0): scaled to (2, 0, 0), turned 90 degrees about z to (0, 2, 0), moved.
  const std::string position = value("/loader", "position");
  EXPECT_EQ(position.substr(0, 14), "10 0 0 10 2 0 ") << position;
  EXPECT_EQ(value("/dofs", "position"), position);
  EXPECT_EQ(value("/dofs", "translation"), "0 0 0");  // not taken from the loader
}

TEST_F(LoaderTest, Scale3dTimesScaleAndTransformation) {
  ASSERT_TRUE(load(
      wrap("<MeshOBJLoader name=\"a\" filename=\"" + data("cube.obj") +
           "\" scale3d=\"1 2 3\" scale=\"2\"/>\n"
           "<MeshOBJLoader name=\"b\" filename=\"" +
           data("cube.obj") +
           "\" transformation=\"1 0 0 5  0 1 0 0  0 0 1 0  0 0 0 1\" translation=\"100 0 0\"/>\n")))
      << messages();
  EXPECT_EQ(value("/a", "position").substr(0, 26), "0 0 0 2 0 0 2 4 0 0 4 0 0 ");
  EXPECT_EQ(value("/b", "position").substr(0, 12), "5 0 0 6 0 0 ");
}

TEST_F(LoaderTest, CreateSubelementsTriangulateFlipAndOnlyAttachedPoints) {
  const std::string mesh =
      write("two.msh",
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n"
            "3 0 1 0\n4 0 0 1\n5 9 9 9\n6 1 1 0\n$EndNodes\n$Elements\n2\n"
            "1 4 0 1 2 3 4\n2 3 0 1 2 6 3\n$EndElements\n");
  ASSERT_TRUE(load(wrap("<MeshGmshLoader name=\"sub\" filename=\"" + mesh +
                        "\" createSubelements=\"true\"/>\n"
                        "<MeshGmshLoader name=\"tri\" filename=\"" +
                        mesh +
                        "\" triangulate=\"1\" flipNormals=\"1\"/>\n"
                        "<MeshGmshLoader name=\"only\" filename=\"" +
                        mesh + "\" onlyAttachedPoints=\"true\"/>\n")))
      << messages();
  // The tetrahedron's 4 faces, then the quad's edges and the faces' edges.
  EXPECT_EQ(value("/sub", "triangles"), "1 2 3 0 3 2 0 1 3 0 2 1");
  EXPECT_EQ(value("/sub", "quads"), "0 1 5 2");
  EXPECT_EQ(value("/sub", "edges"), "2 3 3 1 1 2 2 0 0 3 0 1 1 5 5 2");
  EXPECT_EQ(value("/tri", "quads"), "");
  EXPECT_EQ(value("/tri", "triangles"), "0 5 1 0 2 5");  // (0 1 5) (0 5 2), flipped
  // Point 4 (tag 5) is used by nothing.
  EXPECT_EQ(value("/only", "position"), "0 0 0 1 0 0 0 1 0 0 0 1 1 1 0");
  EXPECT_EQ(value("/only", "quads"), "0 1 4 2");
}

TEST_F(LoaderTest, CorruptFileNamesFileLineAndField) {
  const std::string bad = write("bad.msh",
                                "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n"
                                "1 0 0 0\n2 0 zero 0\n$EndNodes\n");
  EXPECT_FALSE(load(wrap("<MeshGmshLoader name=\"loader\" filename=\"" + bad + "\"/>\n")));
  const Message m = find(MessageLevel::error, "line 7: expected a node coordinate, got 'zero'");
  EXPECT_NE(m.text.find(bad), std::string::npos) << m.text;
  EXPECT_EQ(m.field, "filename");
  EXPECT_EQ(m.componentClass, "MeshGmshLoader");
  EXPECT_EQ(m.where.line, 2);
}

TEST_F(LoaderTest, TruncatedAndGarbageFilesFailCleanlyForEveryLoader) {
  const std::string stl = stlBinary();
  const std::string files[][3] = {
      {"MeshGmshLoader", "cut.msh", gmsh22Binary().substr(0, 150)},
      {"MeshVTKLoader", "cut.vtk", vtkLegacyBinary().substr(0, 120)},
      {"MeshVTKLoader", "garbage.vtu", "<VTKFile type=\"UnstructuredGrid\"><Unstr"},
      {"MeshOBJLoader", "garbage.obj", "v 0 0 0\nf 1 2 3\n"},
      {"MeshSTLLoader", "cut.stl", stl.substr(0, stl.size() - 20)},
      {"MeshGmshLoader", "garbage.msh",
       std::string("\x7f"
                   "ELF\x02\x01\x01",
                   7)}};
  std::string body;
  int i = 0;
  for (const auto& f : files)
    body += "<" + f[0] + " name=\"l" + std::to_string(i++) + "\" filename=\"" + write(f[1], f[2]) +
            "\"/>\n";
  EXPECT_FALSE(load(wrap(body)));
  const auto errors = messagesAt(MessageLevel::error);
  ASSERT_EQ(errors.size(), 6u) << messages();
  for (const Message& e : errors) {
    EXPECT_EQ(e.field, "filename") << e.text;
    EXPECT_NE(e.text.find("cannot read"), std::string::npos) << e.text;
    EXPECT_TRUE(e.text.find("line ") != std::string::npos ||
                e.text.find("byte offset") != std::string::npos)
        << e.text;
  }
}

TEST_F(LoaderTest, MissingFileIsReportedOnce) {
  EXPECT_FALSE(
      load(wrap("<MeshGmshLoader name=\"loader\" filename=\"no/such/mesh.msh\"/>\n"
                "<MeshTopology src=\"@loader\"/>\n")));
  const auto errors = messagesAt(MessageLevel::error);
  ASSERT_EQ(errors.size(), 1u) << messages();
  EXPECT_NE(errors[0].text.find("not found"), std::string::npos);
}

TEST_F(LoaderTest, BadSettingsAreErrors) {
  EXPECT_FALSE(
      load(wrap("<MeshOBJLoader name=\"a\" filename=\"" + data("cube.obj") +
                "\" scale=\"1 2\"/>\n<MeshOBJLoader name=\"b\" filename=\"" + data("cube.obj") +
                "\" transformation=\"1 0 0\"/>\n"
                "<MeshSTLLoader name=\"c\"/>\n")));
  EXPECT_EQ(find(MessageLevel::error, "expected one number (or three), got 2").field, "scale");
  EXPECT_EQ(find(MessageLevel::error, "expected 16 numbers").field, "transformation");
  EXPECT_EQ(find(MessageLevel::error, "no file given").field, "filename");
}

TEST_F(LoaderTest, SofaLiverThroughTheDataPath) {
  const auto share = std::filesystem::path(STROMA_SHARED_DIR) / "sofa/share";
  if (!std::filesystem::exists(share / "mesh/liver.msh"))
    GTEST_SKIP() << "no SOFA meshes (../shared absent)";
  runtime.addDataDirectory(share);
  ASSERT_TRUE(
      load(wrap("<MeshGmshLoader name=\"loader\" filename=\"mesh/liver.msh\"/>\n"
                "<TetrahedronSetTopologyContainer name=\"topo\" src=\"@loader\"/>\n")))
      << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  const Topology* t = topology("/topo");
  EXPECT_EQ(t->nbPoints(), 181u);
  EXPECT_EQ(t->tetrahedra().size(), 596u);
  EXPECT_EQ(t->boundaryTriangles().size() % 2, 0u);  // a closed surface has an even count
  EXPECT_EQ(t->triangles().size(), t->tetrahedronFaces().faces.size());
}

}  // namespace
}  // namespace stroma::test
