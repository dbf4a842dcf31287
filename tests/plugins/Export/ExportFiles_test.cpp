// SPDX-License-Identifier: MIT
// The Export plugin's file writers (VtkFiles.h, MeshFiles.h): what they write reads back, to
// the last bit, through an independent reader (Python's meshio; skipped when absent) and
// through Stroma's own mesh parsers (MeshIO); the .pvd lists its files and times; bad meshes
// and unwritable places are refused with a message.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "MeshFiles.h"
#include "MeshioReader.h"
#include "VtkFiles.h"
#include "formats/FormatParsers.h"
#include "formats/MeshData.h"
#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {
namespace {

using meshio::parseGmsh;
using meshio::parseVtkLegacy;
using meshio::parseVtkXml;
using meshio::readFileBytes;
using vtk::CellType;

/// Two hexahedra side by side and a tetrahedron on top, with points whose coordinates have
/// all their digits, a vector and a scalar field per point, a scalar per cell.
vtk::UnstructuredMesh mixedMesh() {
  vtk::UnstructuredMesh mesh;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        mesh.points.emplace_back(i + std::sqrt(2.0) * 1e-3 * (i + j), j + 0.1 * k / 3.0,
                                 k - std::exp(-(i + j + k)) * 1e-7);
  mesh.points.emplace_back(0.5, 0.5, 1.7);
  const Index h0[8] = {0, 1, 4, 3, 6, 7, 10, 9}, h1[8] = {1, 2, 5, 4, 7, 8, 11, 10};
  const Index t0[4] = {6, 7, 9, 12};
  mesh.addCell(CellType::hexahedron, h0);
  mesh.addCell(CellType::hexahedron, h1);
  mesh.addCell(CellType::tetra, t0);
  vtk::FieldArray velocity{"velocity", 3, {}}, pressure{"pressure", 1, {}};
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    velocity.values.insert(velocity.values.end(), {std::sin(i + 0.1), -1.0 / (i + 3.0), 1e-300});
    pressure.values.push_back(std::cos(i * 0.7) * 1e5);
  }
  mesh.pointFields = {velocity, pressure};
  mesh.cellFields = {{"vonMises", 1, {1.0 / 3.0, 2.5e-17, 123456.789}}};
  return mesh;
}

void expectSamePoints(const MeshioMesh& read, const std::vector<Vec3d>& points) {
  ASSERT_EQ(read.points.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(read.points[i][a], points[i][a]) << "point " << i;
}

/// The cells of `type` of the mesh, as meshio lists them.
std::vector<std::vector<long>> cellsOf(const vtk::UnstructuredMesh& mesh, CellType type) {
  std::vector<std::vector<long>> cells;
  std::size_t next = 0;
  for (CellType t : mesh.cellTypes) {
    const int n = vtk::pointCount(t);
    if (t == type)
      cells.emplace_back(mesh.connectivity.begin() + next, mesh.connectivity.begin() + next + n);
    next += n;
  }
  return cells;
}

TEST(ExportFiles, VtuReadsBackThroughMeshioBitForBit) {
  STROMA_SKIP_WITHOUT_MESHIO();
  TempDir dir;
  const vtk::UnstructuredMesh mesh = mixedMesh();
  std::string error;
  ASSERT_TRUE(vtk::writeVtu(dir.path() / "mixed.vtu", mesh, error)) << error;
  const MeshioMesh read = readWithMeshio(dir.path() / "mixed.vtu");
  expectSamePoints(read, mesh.points);
  EXPECT_EQ(read.cells.at("hexahedron"), cellsOf(mesh, CellType::hexahedron));
  EXPECT_EQ(read.cells.at("tetra"), cellsOf(mesh, CellType::tetra));
  EXPECT_EQ(read.pointData.at("velocity"), mesh.pointFields[0].values);
  EXPECT_EQ(read.components.at("velocity"), 3);
  EXPECT_EQ(read.pointData.at("pressure"), mesh.pointFields[1].values);
  // meshio splits cell data by block (hexahedra, then the tetrahedron): the same order here.
  EXPECT_EQ(read.cellData.at("vonMises"), mesh.cellFields[0].values);
}

TEST(ExportFiles, VtuReadsBackThroughStromasVtuParser) {
  TempDir dir;
  const vtk::UnstructuredMesh mesh = mixedMesh();
  std::string error, bytes;
  ASSERT_TRUE(vtk::writeVtu(dir.path() / "mixed.vtu", mesh, error)) << error;
  ASSERT_TRUE(readFileBytes((dir.path() / "mixed.vtu").string(), bytes, error)) << error;
  MeshData read;
  ASSERT_TRUE(parseVtkXml(bytes, read, error)) << error;
  ASSERT_EQ(read.positions.size(), mesh.points.size());
  for (std::size_t i = 0; i < mesh.points.size(); ++i) EXPECT_EQ(read.positions[i], mesh.points[i]);
  ASSERT_EQ(read.hexahedra.size(), 2u);
  ASSERT_EQ(read.tetrahedra.size(), 1u);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(read.hexahedra[1][k], mesh.connectivity[8 + k]);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(read.tetrahedra[0][k], mesh.connectivity[16 + k]);
}

TEST(ExportFiles, LegacyVtkAndGmshReadBackThroughMeshioAndStroma) {
  TempDir dir;
  const vtk::UnstructuredMesh mesh = mixedMesh();
  std::string error;
  ASSERT_TRUE(vtk::writeVtkLegacy(dir.path() / "mixed.vtk", mesh, error)) << error;
  ASSERT_TRUE(vtk::writeGmsh(dir.path() / "mixed.msh", mesh, error)) << error;
  for (const char* name : {"mixed.vtk", "mixed.msh"}) {
    SCOPED_TRACE(name);
    std::string bytes;
    ASSERT_TRUE(readFileBytes((dir.path() / name).string(), bytes, error)) << error;
    MeshData read;
    ASSERT_TRUE(std::string(name).ends_with(".vtk") ? parseVtkLegacy(bytes, read, error)
                                                    : parseGmsh(bytes, read, error))
        << error;
    ASSERT_EQ(read.positions.size(), mesh.points.size());
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
      EXPECT_EQ(read.positions[i], mesh.points[i]);
    ASSERT_EQ(read.hexahedra.size(), 2u);
    ASSERT_EQ(read.tetrahedra.size(), 1u);
    for (int k = 0; k < 8; ++k) EXPECT_EQ(read.hexahedra[0][k], mesh.connectivity[k]);
  }
  std::string why;
  if (!meshioAvailable(why)) GTEST_SKIP() << why << " (the Stroma half of the test ran)";
  const MeshioMesh vtkRead = readWithMeshio(dir.path() / "mixed.vtk");
  expectSamePoints(vtkRead, mesh.points);
  EXPECT_EQ(vtkRead.cells.at("hexahedron"), cellsOf(mesh, CellType::hexahedron));
  EXPECT_EQ(vtkRead.pointData.at("velocity"), mesh.pointFields[0].values);
  EXPECT_EQ(vtkRead.cellData.at("vonMises"), mesh.cellFields[0].values);
  const MeshioMesh gmshRead = readWithMeshio(dir.path() / "mixed.msh");
  expectSamePoints(gmshRead, mesh.points);
  EXPECT_EQ(gmshRead.cells.at("hexahedron"), cellsOf(mesh, CellType::hexahedron));
  EXPECT_EQ(gmshRead.cells.at("tetra"), cellsOf(mesh, CellType::tetra));
}

TEST(ExportFiles, TetgenReadsBackThroughMeshio) {
  STROMA_SKIP_WITHOUT_MESHIO();
  TempDir dir;
  vtk::UnstructuredMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1.0 / 3, 1.0 / 7, 1.1}};
  const Index t0[4] = {0, 1, 2, 3}, t1[4] = {1, 2, 3, 4};
  mesh.addCell(CellType::tetra, t0);
  mesh.addCell(CellType::tetra, t1);
  std::string error;
  ASSERT_TRUE(vtk::writeTetgen(dir.path() / "two", mesh, error)) << error;
  const MeshioMesh read = readWithMeshio(dir.path() / "two.ele", "tetgen");
  expectSamePoints(read, mesh.points);
  EXPECT_EQ(read.cells.at("tetra"), cellsOf(mesh, CellType::tetra));
}

TEST(ExportFiles, PvdListsItsFilesAndTimes) {
  TempDir dir;
  const std::vector<vtk::CollectionEntry> entries{
      {0.0, "a_000000.vtu"}, {0.1 + 0.2, "a_000003.vtu"}, {1e-9, "name with <&> \".vtu"}};
  std::string error;
  ASSERT_TRUE(vtk::writePvd(dir.path() / "a.pvd", entries, error)) << error;
  if (!std::filesystem::exists("/usr/bin/python3")) GTEST_SKIP() << "/usr/bin/python3 missing";
  // Python's XML parser, independent of the writer: one line "time file" per data set.
  const CliRun run =
      runCli("/usr/bin/python3",
             "-c \"import sys, xml.etree.ElementTree as E; [print(repr(float(d.get('timestep'))) + "
             "'|' + d.get('file')) for d in E.parse(sys.argv[1]).iter('DataSet')]\" \"" +
                 (dir.path() / "a.pvd").string() + "\"");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::istringstream lines(run.output);
  std::string line;
  for (const auto& e : entries) {
    ASSERT_TRUE(std::getline(lines, line));
    const std::size_t bar = line.find('|');
    EXPECT_EQ(std::stod(line.substr(0, bar)), e.time);
    EXPECT_EQ(line.substr(bar + 1), e.file);
  }
  EXPECT_FALSE(std::getline(lines, line)) << "an extra data set: " << line;
}

TEST(ExportFiles, BadMeshesAndPlacesAreRefusedWithAMessage) {
  TempDir dir;
  vtk::UnstructuredMesh mesh = mixedMesh();
  std::string error;
  EXPECT_FALSE(vtk::writeVtu(dir.path() / "missing" / "x.vtu", mesh, error));
  EXPECT_NE(error.find("no folder"), std::string::npos) << error;
  EXPECT_NE(error.find("missing"), std::string::npos) << error;

  vtk::UnstructuredMesh outOfRange = mesh;
  outOfRange.connectivity.back() = 99;
  EXPECT_FALSE(vtk::writeVtu(dir.path() / "x.vtu", outOfRange, error));
  EXPECT_NE(error.find("point 99"), std::string::npos) << error;

  vtk::UnstructuredMesh shortField = mesh;
  shortField.pointFields[1].values.pop_back();
  EXPECT_FALSE(vtk::writeVtkLegacy(dir.path() / "x.vtk", shortField, error));
  EXPECT_NE(error.find("'pressure'"), std::string::npos) << error;

  EXPECT_FALSE(vtk::writeTetgen(dir.path() / "x", mesh, error));
  EXPECT_NE(error.find("tetrahedra only"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.vtu"));
}

}  // namespace
}  // namespace stroma::test
