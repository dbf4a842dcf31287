// SPDX-License-Identifier: MIT
// The file format parsers (parseMesh): each format in ASCII and binary on small meshes whose
// content is known (data/ and MeshWriters.h), SOFA's meshes when ../shared is present, and
// corrupt input (truncated, garbage, bad numbers, indices out of range), which must give an
// error naming the place, never a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "MeshWriters.h"
#include "formats/MeshData.h"
#include "topology/MeshGeometry.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string dataFile(const std::string& name) {
  return readBytes(fs::path(STROMA_SOURCE_DIR) / "tests/plugins/MeshIO/data" / name);
}

MeshData parseOk(const std::string& bytes, MeshFormat format,
                 const MeshParseOptions& options = {}) {
  MeshData mesh;
  std::string error;
  EXPECT_TRUE(parseMesh(bytes, format, mesh, error, options)) << error;
  return mesh;
}

std::string parseError(const std::string& bytes, MeshFormat format) {
  MeshData mesh;
  std::string error;
  EXPECT_FALSE(parseMesh(bytes, format, mesh, error)) << "parsed although corrupt";
  EXPECT_FALSE(error.empty());
  return error;
}

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

void expectCube(const MeshData& mesh) {
  EXPECT_EQ(mesh.positions, cubePoints());
  EXPECT_EQ(mesh.tetrahedra, cubeTetrahedra());
}

// --- Gmsh ---------------------------------------------------------------------------------------

TEST(GmshFormat, Version22AsciiRenumbersTagsAndReadsEveryElementType) {
  const MeshData mesh = parseOk(dataFile("cube_v22.msh"), MeshFormat::gmsh);
  expectCube(mesh);
  EXPECT_EQ(mesh.edges, (std::vector<Edge>{{0, 1}}));
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 2, 1}, {0, 3, 2}}));
  EXPECT_EQ(mesh.hexahedra, (std::vector<Hexahedron>{{0, 1, 2, 3, 4, 5, 6, 7}}));
  EXPECT_TRUE(mesh.warnings.empty());
}

TEST(GmshFormat, Version1) {
  const MeshData mesh = parseOk(dataFile("cube_v1.msh"), MeshFormat::gmsh);
  EXPECT_EQ(mesh.positions, cubePoints());
  EXPECT_EQ(mesh.hexahedra.size(), 1u);
  EXPECT_EQ(mesh.quads, (std::vector<Quad>{{0, 3, 2, 1}}));
}

TEST(GmshFormat, Version41AsciiWithNodeBlocks) {
  const MeshData mesh = parseOk(dataFile("cube_v41.msh"), MeshFormat::gmsh);
  expectCube(mesh);
  EXPECT_EQ(mesh.triangles.size(), 2u);
}

TEST(GmshFormat, Version22Binary) {
  const MeshData mesh = parseOk(gmsh22Binary(), MeshFormat::gmsh);
  expectCube(mesh);
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 3, 2}}));
}

TEST(GmshFormat, Version41Binary) { expectCube(parseOk(gmsh41Binary(), MeshFormat::gmsh)); }

TEST(GmshFormat, PhysicalGroupsOfTheVolumeElementsInEveryVersion) {
  const std::vector<int> ones(5, 1);
  // 2.2: the first tag; 1: reg-phys.
  const MeshData v22 = parseOk(dataFile("cube_v22.msh"), MeshFormat::gmsh);
  EXPECT_EQ(v22.tetrahedronGroups, ones);
  EXPECT_EQ(v22.hexahedronGroups, std::vector<int>{1});
  EXPECT_EQ(parseOk(dataFile("cube_v1.msh"), MeshFormat::gmsh).hexahedronGroups,
            std::vector<int>{1});
  EXPECT_EQ(parseOk(gmsh22Binary(), MeshFormat::gmsh).tetrahedronGroups, ones);
  // 4.1: the group of the elements' entity in $Entities; none there gives 0.
  std::string text = dataFile("cube_v41.msh");
  EXPECT_EQ(parseOk(text, MeshFormat::gmsh).tetrahedronGroups, std::vector<int>(5, 0));
  const std::string volume = "1 0 0 0 1 1 1 0 0\n";
  ASSERT_NE(text.find(volume), std::string::npos);
  text.replace(text.find(volume), volume.size(), "1 0 0 0 1 1 1 1 -7 0\n");
  EXPECT_EQ(parseOk(text, MeshFormat::gmsh).tetrahedronGroups, std::vector<int>(5, 7));
  EXPECT_EQ(parseOk(gmsh41Binary(), MeshFormat::gmsh).tetrahedronGroups, std::vector<int>(5, 0));
  EXPECT_EQ(parseOk(gmsh41Binary(12), MeshFormat::gmsh).tetrahedronGroups,
            std::vector<int>(5, 12));
  // A truncated $Entities section says what it expected.
  const std::string binary = gmsh41Binary(12);
  EXPECT_CONTAINS(parseError(binary.substr(0, binary.find("$EndEntities") - 20), MeshFormat::gmsh),
                  "byte offset");
  text.replace(text.find("1 0 0 0 1 1 1 1 -7 0\n"), 21, "1 0 0 0 1 1 1 x\n");
  EXPECT_CONTAINS(parseError(text, MeshFormat::gmsh), "the number of physical groups");
}

TEST(GmshFormat, SecondOrderElementsKeepTheirCornersWithAWarning) {
  const std::string file =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n10\n"
      "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 .5 0 0\n6 .5 .5 0\n7 0 .5 0\n8 0 0 .5\n9 .5 0 .5\n"
      "10 0 .5 .5\n$EndNodes\n$Elements\n2\n1 11 0 1 2 3 4 5 6 7 8 10 9\n2 6 0 1 2 3 4 5 6\n"
      "$EndElements\n";
  const MeshData mesh = parseOk(file, MeshFormat::gmsh);
  EXPECT_EQ(mesh.tetrahedra, (std::vector<Tetrahedron>{{0, 1, 2, 3}}));
  ASSERT_EQ(mesh.warnings.size(), 2u);
  EXPECT_CONTAINS(mesh.warnings[0], "prism");
  EXPECT_CONTAINS(mesh.warnings[1], "second-order tetrahedron");
}

TEST(GmshFormat, Errors) {
  std::string text = dataFile("cube_v22.msh");
  // Truncated in the elements.
  EXPECT_CONTAINS(parseError(text.substr(0, text.find("$EndElements") - 8), MeshFormat::gmsh),
                  "line ");
  // Garbage.
  EXPECT_CONTAINS(parseError("this is not a mesh\n", MeshFormat::gmsh), "$MeshFormat");
  // A bad number, with its line.
  std::string bad = text;
  bad.replace(bad.find("20 1 0 0"), 8, "20 1 x 0");
  EXPECT_CONTAINS(parseError(bad, MeshFormat::gmsh),
                  "line 11: expected a node coordinate, got 'x'");
  // A node that does not exist.
  bad = text;
  bad.replace(bad.find("$EndElements") - 3, 2, "99");
  EXPECT_CONTAINS(parseError(bad, MeshFormat::gmsh), "uses node 99");
  // An unknown element type and an unsupported version.
  bad = text;
  bad.replace(bad.find("\n1 15 "), 6, "\n1 77 ");
  EXPECT_CONTAINS(parseError(bad, MeshFormat::gmsh), "unsupported Gmsh element type 77");
  bad = text;
  bad.replace(bad.find("2.2 0 8"), 7, "3.0 0 8");
  EXPECT_CONTAINS(parseError(bad, MeshFormat::gmsh), "unsupported Gmsh format version");
  // Binary data cut short: the byte offset.
  const std::string binary = gmsh22Binary();
  EXPECT_CONTAINS(parseError(binary.substr(0, binary.size() - 40), MeshFormat::gmsh),
                  "byte offset");
  const std::string binary4 = gmsh41Binary();
  EXPECT_CONTAINS(parseError(binary4.substr(0, 200), MeshFormat::gmsh), "byte offset");
}

// --- VTK ----------------------------------------------------------------------------------------

TEST(VtkFormat, LegacyAsciiUnstructuredGrid) {
  const MeshData mesh = parseOk(dataFile("cube_grid.vtk"), MeshFormat::vtk);
  expectCube(mesh);
  EXPECT_EQ(mesh.hexahedra.size(), 1u);
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 2, 1}}));
  ASSERT_EQ(mesh.normals.size(), 8u);
  EXPECT_EQ(mesh.normals[3], Vec3d(0, 0, 1));
}

TEST(VtkFormat, LegacyAsciiPolyData) {
  const MeshData mesh = parseOk(dataFile("cube_surface.vtk"), MeshFormat::vtk);
  EXPECT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(mesh.quads.size(), 6u);
  EXPECT_EQ(mesh.edges, (std::vector<Edge>{{0, 1}, {1, 2}}));
}

TEST(VtkFormat, LegacyBinary) {
  const MeshData mesh = parseOk(vtkLegacyBinary(), MeshFormat::vtk);
  expectCube(mesh);
  EXPECT_EQ(mesh.normals.size(), 8u);
}

TEST(VtkFormat, XmlAsciiAndBinary) {
  MeshData mesh = parseOk(dataFile("cube.vtu"), MeshFormat::vtk);
  expectCube(mesh);
  EXPECT_EQ(mesh.hexahedra.size(), 1u);
  EXPECT_EQ(mesh.normals.size(), 8u);
  expectCube(parseOk(vtuBinary(), MeshFormat::vtk));
}

TEST(VtkFormat, Errors) {
  const std::string text = dataFile("cube_grid.vtk");
  EXPECT_CONTAINS(parseError(text.substr(0, text.find("CELL_TYPES") - 10), MeshFormat::vtk),
                  "line ");
  EXPECT_CONTAINS(parseError("garbage\x01\x02", MeshFormat::vtk),
                  "line 1: expected '# vtk DataFile");
  std::string bad = text;
  bad.replace(bad.find("4 1 0 5 2"), 9, "4 1 0 5 9");
  EXPECT_CONTAINS(parseError(bad, MeshFormat::vtk),
                  "uses point 9, out of range: there are 8 points");
  bad = text;
  bad.replace(bad.find("UNSTRUCTURED_GRID"), 17, "STRUCTURED_POINTS");
  EXPECT_CONTAINS(parseError(bad, MeshFormat::vtk), "unsupported dataset");
  const std::string binary = vtkLegacyBinary();
  EXPECT_CONTAINS(parseError(binary.substr(0, 150), MeshFormat::vtk), "byte offset");
  // XML.
  const std::string xml = dataFile("cube.vtu");
  EXPECT_CONTAINS(parseError(xml.substr(0, xml.size() / 2), MeshFormat::vtk), "malformed XML");
  bad = xml;
  bad.replace(bad.find("NumberOfPoints=\"8\""), 18, "NumberOfPoints=\"9\"");
  EXPECT_CONTAINS(parseError(bad, MeshFormat::vtk), "points: expected 27 numbers");
  std::string cut = vtuBinary();
  cut.replace(cut.find("format=\"binary\">") + 16, 8, "");
  EXPECT_FALSE(parseError(cut, MeshFormat::vtk).empty());
}

// --- OBJ ----------------------------------------------------------------------------------------

TEST(ObjFormat, FacesOfEveryFormAndLines) {
  const MeshData mesh = parseOk(dataFile("cube.obj"), MeshFormat::obj);
  EXPECT_EQ(mesh.positions, cubePoints());
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 2, 1}, {0, 3, 2}}));
  EXPECT_EQ(mesh.quads, (std::vector<Quad>{
                            {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}));
  EXPECT_EQ(mesh.edges, (std::vector<Edge>{{0, 1}, {1, 2}}));
  ASSERT_EQ(mesh.normals.size(), 8u);
  EXPECT_EQ(mesh.normals[6], Vec3d(0, 0, 1));   // from the top face
  EXPECT_EQ(mesh.normals[0], Vec3d(0, -1, 0));  // from the front face
  ASSERT_EQ(mesh.texcoords.size(), 8u);
  EXPECT_EQ(mesh.texcoords[5], Vec2d(0, 1));  // the last face giving point 6 one: right face
}

TEST(ObjFormat, PolygonsAreFansAndSeamsDuplicatePoints) {
  const std::string pentagon = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n";
  EXPECT_EQ(parseOk(pentagon, MeshFormat::obj).triangles,
            (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  MeshParseOptions seams;
  seams.handleSeams = true;
  const MeshData mesh = parseOk(dataFile("cube.obj"), MeshFormat::obj, seams);
  EXPECT_EQ(mesh.positions.size(), 19u);  // distinct (v, vt, vn) corners
  EXPECT_EQ(mesh.normals.size(), 19u);
  EXPECT_EQ(mesh.quads.size(), 5u);
}

TEST(ObjFormat, Errors) {
  EXPECT_CONTAINS(parseError("v 0 0 0\nv 1 0 x\n", MeshFormat::obj),
                  "line 2: expected a number in the vertex, got 'x'");
  EXPECT_CONTAINS(parseError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 12\n", MeshFormat::obj),
                  "line 4: vertex index 12 is out of range: the file defines 3 vertices");
  EXPECT_CONTAINS(parseError("v 0 0 0\nf 1 0 1\n", MeshFormat::obj), "bad vertex index 0");
  const std::string text = dataFile("cube.obj");
  EXPECT_CONTAINS(parseError(text.substr(0, text.find("v 1 1 1") + 5), MeshFormat::obj),
                  "expected 3 numbers in the vertex, got 2");
  EXPECT_CONTAINS(parseError("v \x01\x02\x03 garbage\n", MeshFormat::obj), "line 1");
  // A bad texture coordinate index loses only the texture coordinate.
  const MeshData mesh = parseOk("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/4 2/5 3/6\n", MeshFormat::obj);
  EXPECT_EQ(mesh.triangles.size(), 1u);
  ASSERT_EQ(mesh.warnings.size(), 1u);
  EXPECT_CONTAINS(mesh.warnings[0], "line 4");
}

// --- STL ----------------------------------------------------------------------------------------

TEST(StlFormat, AsciiMergesRepeatedPoints) {
  const MeshData mesh = parseOk(dataFile("cube_ascii.stl"), MeshFormat::stl);
  EXPECT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.normals.size(), 8u);
  MeshParseOptions keep;
  keep.mergePositions = false;
  EXPECT_EQ(parseOk(dataFile("cube_ascii.stl"), MeshFormat::stl, keep).positions.size(), 36u);
}

TEST(StlFormat, BinaryStartingWithSolid) {
  const MeshData mesh = parseOk(stlBinary(), MeshFormat::stl);
  EXPECT_EQ(mesh.positions.size(), 8u);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  // Outward triangles: positive volume by the divergence theorem.
  double volume = 0;
  for (const Triangle& t : mesh.triangles)
    volume += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]])) / 6;
  EXPECT_NEAR(volume, 1.0, 1e-12);
  // The normal of a corner is the mean of its triangles': pointing out of the cube.
  EXPECT_NEAR(mesh.normals[0].norm(), 1.0, 1e-12);
  EXPECT_TRUE((mesh.normals[0].array() < 0).all()) << mesh.normals[0].transpose();
}

TEST(StlFormat, Errors) {
  const std::string binary = stlBinary();
  EXPECT_CONTAINS(parseError(binary.substr(0, 84 + 50 * 3 + 7), MeshFormat::stl),
                  "byte offset 84: expected 12 triangles");
  EXPECT_CONTAINS(parseError(binary.substr(0, 40), MeshFormat::stl), "expected 'endsolid'");
  std::string shortBinary = binary.substr(0, 60);
  shortBinary[50] = '\0';
  EXPECT_CONTAINS(parseError(shortBinary, MeshFormat::stl), "byte offset 0");
  const std::string text = dataFile("cube_ascii.stl");
  EXPECT_CONTAINS(parseError(text.substr(0, text.size() / 2), MeshFormat::stl), "line ");
  EXPECT_CONTAINS(parseError("solid x\n facet nromal 0 0 1\n", MeshFormat::stl),
                  "line 2: expected 'normal', got 'nromal'");
}

// --- Any corrupt input: an error, never a crash -------------------------------------------------

struct Sample {
  std::string name;
  std::string bytes;
  MeshFormat format;
};

std::vector<Sample> samples() {
  return {{"cube_v22.msh", dataFile("cube_v22.msh"), MeshFormat::gmsh},
          {"cube_v1.msh", dataFile("cube_v1.msh"), MeshFormat::gmsh},
          {"cube_v41.msh", dataFile("cube_v41.msh"), MeshFormat::gmsh},
          {"gmsh 2.2 binary", gmsh22Binary(), MeshFormat::gmsh},
          {"gmsh 4.1 binary", gmsh41Binary(), MeshFormat::gmsh},
          {"cube_grid.vtk", dataFile("cube_grid.vtk"), MeshFormat::vtk},
          {"cube_surface.vtk", dataFile("cube_surface.vtk"), MeshFormat::vtk},
          {"vtk binary", vtkLegacyBinary(), MeshFormat::vtk},
          {"cube.vtu", dataFile("cube.vtu"), MeshFormat::vtk},
          {"vtu binary", vtuBinary(), MeshFormat::vtk},
          {"cube.obj", dataFile("cube.obj"), MeshFormat::obj},
          {"cube_ascii.stl", dataFile("cube_ascii.stl"), MeshFormat::stl},
          {"stl binary", stlBinary(), MeshFormat::stl}};
}

/// A parse that succeeds gives elements inside the points; one that fails says why.
void expectCleanOutcome(const std::string& bytes, MeshFormat format, const std::string& what) {
  MeshData mesh;
  std::string error;
  if (parseMesh(bytes, format, mesh, error)) {
    auto inRange = [&](const auto& elements) {
      for (const auto& e : elements)
        for (Index v : e) ASSERT_LT(v, mesh.positions.size()) << what;
    };
    inRange(mesh.edges);
    inRange(mesh.triangles);
    inRange(mesh.quads);
    inRange(mesh.tetrahedra);
    inRange(mesh.hexahedra);
  } else {
    EXPECT_FALSE(error.empty()) << what;
  }
}

TEST(MeshFormats, EveryTruncationIsHandled) {
  for (const Sample& s : samples())
    for (std::size_t n = 0; n < s.bytes.size(); ++n)
      expectCleanOutcome(s.bytes.substr(0, n), s.format, s.name + " cut at " + std::to_string(n));
}

TEST(MeshFormats, RandomByteChangesAreHandled) {
  std::mt19937 random(12345);
  for (const Sample& s : samples())
    for (int trial = 0; trial < 300; ++trial) {
      std::string bytes = s.bytes;
      const int changes = 1 + trial % 4;
      for (int c = 0; c < changes; ++c)
        bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
      expectCleanOutcome(bytes, s.format, s.name + " trial " + std::to_string(trial));
    }
}

TEST(MeshFormats, HugeCountsAreRefusedBeforeAllocating) {
  EXPECT_CONTAINS(parseError("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n99999999999\n1 0 0 0\n",
                             MeshFormat::gmsh),
                  "out of range");
  std::string binary = stlBinary();
  binary[80] = binary[81] = binary[82] = binary[83] = '\xff';
  EXPECT_CONTAINS(parseError(binary, MeshFormat::stl), "expected 4294967295 triangles");
}

TEST(MeshFormats, FormatFromFileName) {
  EXPECT_EQ(meshFormatFromFileName("a/b/liver.MSH"), MeshFormat::gmsh);
  EXPECT_EQ(meshFormatFromFileName("x.vtu"), MeshFormat::vtk);
  EXPECT_EQ(meshFormatFromFileName("x.obj"), MeshFormat::obj);
  EXPECT_EQ(meshFormatFromFileName("x.stl"), MeshFormat::stl);
  EXPECT_FALSE(meshFormatFromFileName("x.off"));
  EXPECT_FALSE(meshFormatFromFileName("noextension"));
}

// --- SOFA's meshes ------------------------------------------------------------------------------

class SofaMeshes : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(meshDir()))
      GTEST_SKIP() << "no SOFA meshes at " << meshDir() << " (../shared absent)";
  }
  static fs::path meshDir() { return fs::path(STROMA_SHARED_DIR) / "sofa/share/mesh"; }
  MeshData read(const std::string& name, MeshFormat format) {
    MeshData mesh;
    std::string error;
    EXPECT_TRUE(readMeshFile((meshDir() / name).string(), format, mesh, error))
        << name << ": " << error;
    return mesh;
  }
};

TEST_F(SofaMeshes, GmshLiverIsPositivelyOriented) {
  const MeshData liver = read("liver.msh", MeshFormat::gmsh);
  EXPECT_EQ(liver.positions.size(), 181u);
  EXPECT_EQ(liver.tetrahedra.size(), 596u);
  const QualityReport quality = checkTetrahedra(liver.positions, liver.tetrahedra);
  EXPECT_TRUE(quality.empty()) << quality.inverted.size() << " inverted";
  const MeshData torus = read("torus_low_res.msh", MeshFormat::gmsh);
  EXPECT_EQ(torus.tetrahedra.size(), 862u);
  EXPECT_EQ(torus.triangles.size(), 408u);
  EXPECT_EQ(torus.edges.size(), 200u);
  const MeshData cube4 = read("msh4_cube.msh", MeshFormat::gmsh);
  EXPECT_EQ(cube4.positions.size(), 14u);
  EXPECT_GT(cube4.tetrahedra.size(), 0u);
  EXPECT_TRUE(checkTetrahedra(cube4.positions, cube4.tetrahedra).empty());
}

TEST_F(SofaMeshes, Vtk) {
  const MeshData raptor = read("raptorTetra_8418.vtu", MeshFormat::vtk);
  EXPECT_EQ(raptor.positions.size(), 2996u);
  EXPECT_EQ(raptor.tetrahedra.size(), 8418u);
  const MeshData bunny = read("Bunny.vtk", MeshFormat::vtk);  // XML content in a .vtk file
  EXPECT_EQ(bunny.positions.size(), 1911u);
  EXPECT_EQ(bunny.tetrahedra.size(), 5897u);
  const MeshData liver = read("liver.vtk", MeshFormat::vtk);  // legacy binary POLYDATA
  EXPECT_EQ(liver.positions.size(), 5008u);
  EXPECT_EQ(liver.triangles.size(), 10000u);
  const MeshData voxels = read("vox8_binary.vtk", MeshFormat::vtk);
  EXPECT_EQ(voxels.hexahedra.size(), 8u);
  EXPECT_TRUE(checkHexahedra(voxels.positions, voxels.hexahedra).empty());
  const MeshData volume = read("SOFA_volume.vtk", MeshFormat::vtk);
  EXPECT_EQ(volume.tetrahedra.size(), 2564u);
  EXPECT_EQ(volume.triangles.size(), 6057u);
  EXPECT_EQ(volume.edges.size(), 4451u);
  EXPECT_EQ(read("test_quad.vtk", MeshFormat::vtk).quads.size(), 288u);
}

TEST_F(SofaMeshes, ObjAndStl) {
  const MeshData liver = read("liver-smooth.obj", MeshFormat::obj);
  EXPECT_EQ(liver.positions.size(), 2194u);
  EXPECT_EQ(liver.triangles.size(), 4384u);
  const MeshData bunny = read("Bunny.stl", MeshFormat::stl);  // binary with a text header
  EXPECT_EQ(bunny.triangles.size(), 2728u);
  EXPECT_EQ(bunny.positions.size(), 1366u);
  const MeshData pliers = read("pliers_binary.stl", MeshFormat::stl);
  EXPECT_EQ(pliers.triangles.size(), 10712u);
  EXPECT_EQ(pliers.positions.size(), 5356u);
  const MeshData knot = read("circle_knot_ascii.stl", MeshFormat::stl);  // ends with "end solid"
  EXPECT_EQ(knot.triangles.size(), 12288u);
  EXPECT_EQ(knot.positions.size(), 6144u);
}

TEST_F(SofaMeshes, SofasBrokenTestFilesGiveErrors) {
  for (const auto& [name, format] :
       {std::pair{"Armadillo_Tetra_4406_for_test_broken.vtu", MeshFormat::vtk},
        std::pair{"liver_for_test_broken.vtk", MeshFormat::vtk},
        std::pair{"6_tetra_bad.msh", MeshFormat::gmsh}}) {
    MeshData mesh;
    std::string error;
    const bool ok = readMeshFile((meshDir() / name).string(), format, mesh, error);
    if (std::string(name) == "6_tetra_bad.msh") {
      // Readable; one of its tetrahedra is inverted (a job for the topology's checks).
      ASSERT_TRUE(ok) << error;
      EXPECT_EQ(checkTetrahedra(mesh.positions, mesh.tetrahedra).inverted.size(), 1u);
    } else {
      EXPECT_FALSE(ok) << name;
      EXPECT_FALSE(error.empty());
    }
  }
}

}  // namespace
}  // namespace stroma::test
