// SPDX-License-Identifier: MIT
// The Export plugin's SOFA components in inline scenes: WriteState then ReadState replays a
// trajectory to the last bit (plain and gzip), ReadState reads SOFA's own WriteState output,
// VTKExporter's and MeshExporter's files read back through meshio (skipped when absent) and
// Stroma's mesh loaders, and every component refuses bad attribute values with a message
// naming the field (and the file's line for a malformed state file).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "MeshioReader.h"
#include "core/PathResolver.h"
#include "core/StateTypes.h"
#include "formats/FormatParsers.h"
#include "formats/MeshData.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;
using State = MechanicalState<Vec3Types>;

/// A 3 x 3 x 5 grid beam clamped at z = 0, falling under gravity (y), with `extra` components.
std::string beamScene(const std::string& extra) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <Node name="Beam">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="100" tolerance="1e-12" threshold="1e-16"/>
    <RegularGridTopology name="grid" nx="3" ny="3" nz="5" xmin="0" xmax="2" ymin="0" ymax="2"
                         zmin="0" zmax="4"/>
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="10"/>
    <HexahedronFEMForceField name="fem" youngModulus="2000" poissonRatio="0.3"/>
    <FixedProjectiveConstraint indices="0 1 2 3 4 5 6 7 8"/>
    )" + extra +
         R"(
  </Node>
</Node>)";
}

/// The same grid without a solver: what ReadState sets is what the scene shows.
std::string replayScene(
    const std::string& readState,
    const std::string& grid =
        R"(nx="3" ny="3" nz="5" xmin="0" xmax="2" ymin="0" ymax="2" zmin="0" zmax="4")") {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <Node name="Beam">
    <RegularGridTopology name="grid" )" +
         grid + R"(/>
    <MechanicalObject name="dofs"/>
    )" + readState +
         R"(
  </Node>
</Node>)";
}

class SceneUnderTest {
 public:
  SceneUnderTest() : scene(runtime) { useTestPlugins(runtime); }
  bool load(const std::string& xml) { return scene.loadString(xml, "inline.scn"); }
  State& dofs() {
    std::string why;
    auto* state = dynamic_cast<State*>(resolveObjectPath(scene.root(), "@/Beam/dofs", why));
    EXPECT_NE(state, nullptr) << why;
    return *state;
  }
  std::vector<Vec3d> positions() { return dofs().readCoord(VecId::position()); }
  std::vector<Vec3d> velocities() { return dofs().readDeriv(VecId::velocity()); }
  const Topology& grid() {
    std::string why;
    auto* t = dynamic_cast<Topology*>(resolveObjectPath(scene.root(), "@/Beam/grid", why));
    EXPECT_NE(t, nullptr) << why;
    return *t;
  }

  Runtime runtime;
  Scene scene;
};

// --- WriteState and ReadState ---------------------------------------------------------------

void expectReplay(const std::string& fileName) {
  TempDir dir;
  const std::string file = (dir.path() / fileName).string();
  std::vector<std::vector<Vec3d>> x, v;
  {
    SceneUnderTest a;
    ASSERT_TRUE(a.load(beamScene("<WriteState filename=\"" + file +
                                 "\" period=\"0.01\" writeX=\"1\" writeV=\"1\"/>")))
        << describe(a.scene.log());
    for (int k = 0; k < 10; ++k) {
      ASSERT_TRUE(a.scene.step());
      x.push_back(a.positions());
      v.push_back(a.velocities());
    }
  }  // the scene closes its file
  SceneUnderTest b;
  ASSERT_TRUE(b.load(replayScene("<ReadState filename=\"" + file + "\"/>")))
      << describe(b.scene.log());
  const std::vector<Vec3d> rest = b.positions();
  for (int k = 0; k < 10; ++k) {
    ASSERT_TRUE(b.scene.step());
    EXPECT_EQ(b.positions(), x[k]) << "step " << k + 1;
    EXPECT_EQ(b.velocities(), v[k]) << "step " << k + 1;
  }
  // The beam moved (else the comparison tests nothing).
  EXPECT_GT((x.back()[44] - rest[44]).norm(), 1e-3);
}

TEST(WriteStateReadState, ReplayTheTrajectoryToTheLastBit) { expectReplay("beam.state"); }

TEST(WriteStateReadState, ReplayTheTrajectoryThroughGzip) { expectReplay("beam.state.gz"); }

TEST(WriteState, WritesSofasFormatAtItsTimes) {
  TempDir dir;
  const fs::path file = dir.path() / "some.state";
  SceneUnderTest a;
  // Times 0.02 and 0.05, then every 0.03: 0.02, 0.05, 0.08 within 10 steps; the DOFs 44 and 2.
  ASSERT_TRUE(a.load(beamScene("<WriteState filename=\"" + file.string() +
                               "\" time=\"0.02 0.05\" period=\"0.03\" writeX0=\"1\" "
                               "writeV=\"1\" DOFsX=\"44 2\" DOFsV=\"44\"/>")))
      << describe(a.scene.log());
  std::vector<Vec3d> x8, v8;
  for (int k = 1; k <= 10; ++k) {
    ASSERT_TRUE(a.scene.step());
    if (k == 8) x8 = a.positions(), v8 = a.velocities();
  }
  a.scene.unload();
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 12u);  // 3 records of T=, X=, X0=, V=
  EXPECT_EQ(lines[0].substr(0, 3), "T= ");
  EXPECT_NEAR(std::stod(lines[0].substr(3)), 0.02, 1e-12);
  EXPECT_NEAR(std::stod(lines[4].substr(3)), 0.05, 1e-12);
  EXPECT_NEAR(std::stod(lines[8].substr(3)), 0.08, 1e-12);
  EXPECT_EQ(lines[9].substr(0, 5), "  X= ");
  EXPECT_EQ(lines[10].substr(0, 6), "  X0= ");
  EXPECT_EQ(lines[11].substr(0, 5), "  V= ");
  std::istringstream xs(lines[9].substr(5));
  std::vector<double> values;
  for (double value; xs >> value;) values.push_back(value);
  // The record at 0.08 holds the state after step 8: points 44 and 2, in that order.
  EXPECT_EQ(values, (std::vector<double>{x8[44].x(), x8[44].y(), x8[44].z(), x8[2].x(), x8[2].y(),
                                         x8[2].z()}));
  std::istringstream vs(lines[11].substr(5));
  values.clear();
  for (double value; vs >> value;) values.push_back(value);
  EXPECT_EQ(values, (std::vector<double>{v8[44].x(), v8[44].y(), v8[44].z()}));
}

TEST(WriteState, WritesAfterTheStepsOfAnyAnimationLoop) {
  // StepListener is called by the scene around whatever loop steps it: FreeMotionAnimationLoop
  // (no constraint here) has its own step.
  TempDir dir;
  const fs::path file = dir.path() / "free.state";
  std::string scene = beamScene("<WriteState filename=\"" + file.string() + "\" period=\"0.01\"/>");
  scene.insert(scene.find("<Node name=\"Beam\">"),
               "<FreeMotionAnimationLoop/>\n  <GenericConstraintSolver/>\n  ");
  SceneUnderTest s;
  ASSERT_TRUE(s.load(scene)) << describe(s.scene.log());
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(s.scene.step());
  const std::vector<Vec3d> x = s.positions();
  s.scene.unload();
  SceneUnderTest replay;
  ASSERT_TRUE(replay.load(replayScene("<ReadState filename=\"" + file.string() + "\"/>")))
      << describe(replay.scene.log());
  EXPECT_GT((x[44] - replay.positions()[44]).norm(), 1e-4) << "the beam did not fall";
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(replay.scene.step());
  EXPECT_EQ(replay.positions(), x);
  std::ifstream in(file);
  int records = 0;
  for (std::string line; std::getline(in, line);) records += line.starts_with("T= ");
  EXPECT_EQ(records, 6);  // t = 0 to 0.05
}

/// The X= numbers of the record "T= time" of a SOFA state file, read by the test itself.
std::vector<double> recordPositions(const fs::path& file, const std::string& time) {
  std::ifstream in(file);
  std::vector<double> values;
  for (std::string line; std::getline(in, line);)
    if (line == "T= " + time) {
      std::getline(in, line);
      std::istringstream numbers(line.substr(line.find('=') + 1));
      for (double v; numbers >> v;) values.push_back(v);
      break;
    }
  return values;
}

TEST(ReadState, ReadsAFileWrittenBySofasWriteState) {
  // SOFA's WriteState.scn beam (3 x 3 x 7 grid, 3 x 3 x 7 units), its positions and
  // velocities from t = 0 to 0.1 as runSofa wrote them (data/make-sofa-beam-writestate.sh).
  const fs::path file =
      fs::path(STROMA_SOURCE_DIR) / "tests/plugins/Export/data/sofa-beam-writestate.txt";
  SceneUnderTest s;
  ASSERT_TRUE(s.load(
      replayScene("<ReadState name=\"StateReader\" filename=\"" + file.string() + "\"/>",
                  R"(nx="3" ny="3" nz="7" xmin="0" xmax="3" ymin="0" ymax="3" zmin="0" zmax="7")")))
      << describe(s.scene.log());
  const char* times[] = {"0.01", "0.02", "0.03", "0.04", "0.05",
                         "0.06", "0.07", "0.08", "0.09", "0.1"};
  for (const char* time : times) {
    ASSERT_TRUE(s.scene.step());
    const std::vector<double> expected = recordPositions(file, time);
    const std::vector<Vec3d> x = s.positions();
    ASSERT_EQ(expected.size(), 3 * x.size()) << "T= " << time;
    for (std::size_t i = 0; i < x.size(); ++i)
      for (int a = 0; a < 3; ++a) EXPECT_EQ(x[i][a], expected[3 * i + a]) << "T= " << time;
  }
  // SOFA's beam fell: its free end is below where it started.
  EXPECT_LT(s.positions().back().y(), 3.0 - 1e-3);
}

TEST(ReadState, ShiftScaleTranslationAndLoop) {
  const fs::path file =
      fs::path(STROMA_SOURCE_DIR) / "tests/plugins/Export/data/sofa-beam-writestate.txt";
  SceneUnderTest s;
  // shift 0.05: after the first step (t = 0.01) the record of 0.06; positions doubled, moved.
  ASSERT_TRUE(s.load(
      replayScene("<ReadState filename=\"" + file.string() +
                      "\" shift=\"0.05\" scalePos=\"2\" translation=\"1 0 0\" loop=\"1\"/>",
                  R"(nx="3" ny="3" nz="7" xmin="0" xmax="3" ymin="0" ymax="3" zmin="0" zmax="7")")))
      << describe(s.scene.log());
  ASSERT_TRUE(s.scene.step());
  std::vector<double> expected = recordPositions(file, "0.06");
  EXPECT_EQ(s.positions()[62].x(), 2 * expected[3 * 62] + 1);
  EXPECT_EQ(s.positions()[62].y(), 2 * expected[3 * 62 + 1]);
  // Loop: the file lasts 0.1 + one spacing 0.01, so t = 0.07 + 0.05 = 0.12 reads 0.01.
  for (int k = 0; k < 6; ++k) ASSERT_TRUE(s.scene.step());
  expected = recordPositions(file, "0.01");
  EXPECT_NEAR(s.positions()[62].y(), 2 * expected[3 * 62 + 1], 1e-12);
}

TEST(ReadState, IntervalReadsOnlyThatOften) {
  const fs::path file =
      fs::path(STROMA_SOURCE_DIR) / "tests/plugins/Export/data/sofa-beam-writestate.txt";
  SceneUnderTest s;
  ASSERT_TRUE(s.load(
      replayScene("<ReadState filename=\"" + file.string() + "\" interval=\"0.03\"/>",
                  R"(nx="3" ny="3" nz="7" xmin="0" xmax="3" ymin="0" ymax="3" zmin="0" zmax="7")")))
      << describe(s.scene.log());
  // Read at t = 0 (the first step's begin), then not before t = 0.03.
  const std::vector<double> atZero = recordPositions(file, "0"),
                            atThree = recordPositions(file, "0.03");
  ASSERT_NE(atZero[3 * 62 + 1], atThree[3 * 62 + 1]);
  for (int k = 1; k <= 3; ++k) {
    ASSERT_TRUE(s.scene.step());
    EXPECT_EQ(s.positions()[62].y(), (k < 3 ? atZero : atThree)[3 * 62 + 1]) << "step " << k;
  }
}

// --- VTKExporter and MeshExporter ------------------------------------------------------------

TEST(VTKExporter, FilesReadBackThroughMeshio) {
  STROMA_SKIP_WITHOUT_MESHIO();
  TempDir dir;
  const std::string base = (dir.path() / "beam").string();
  SceneUnderTest s;
  ASSERT_TRUE(s.load(beamScene("<VTKExporter filename=\"" + base +
                               "\" edges=\"0\" hexas=\"1\" pointsDataFields=\"dofs.velocity\" "
                               "exportEveryNumberOfSteps=\"2\" exportAtBegin=\"1\"/>"
                               "<VTKExporter name=\"legacy\" filename=\"" +
                               base +
                               "-legacy\" XMLformat=\"0\" edges=\"0\" hexas=\"1\" "
                               "overwrite=\"1\" exportEveryNumberOfSteps=\"4\"/>")))
      << describe(s.scene.log());
  for (int k = 0; k < 4; ++k) ASSERT_TRUE(s.scene.step());
  ASSERT_TRUE(fs::exists(base + "0.vtu"));  // at begin (SOFA's names: filename + number)
  ASSERT_TRUE(fs::exists(base + "1.vtu"));  // step 2
  ASSERT_FALSE(fs::exists(base + "3.vtu"));
  const std::vector<Vec3d> x = s.positions(), v = s.velocities();
  for (const std::string& name : {base + "2.vtu", base + "-legacy.vtk"}) {
    SCOPED_TRACE(name);
    const MeshioMesh read = readWithMeshio(name);
    ASSERT_EQ(read.points.size(), x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      for (int a = 0; a < 3; ++a) EXPECT_EQ(read.points[i][a], x[i][a]);
    const auto& hexahedra = s.grid().hexahedra();
    ASSERT_EQ(read.cells.at("hexahedron").size(), hexahedra.size());
    for (std::size_t e = 0; e < hexahedra.size(); ++e)
      for (int k = 0; k < 8; ++k) EXPECT_EQ(read.cells.at("hexahedron")[e][k], hexahedra[e][k]);
  }
  const MeshioMesh read = readWithMeshio(base + "2.vtu");
  const std::vector<double>& velocity = read.pointData.at("velocity");
  ASSERT_EQ(velocity.size(), 3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(velocity[3 * i + a], v[i][a]);
}

TEST(MeshExporter, OutputReadsBackThroughStromasLoadersAndMeshio) {
  TempDir dir;
  const std::string base = (dir.path() / "mesh").string();
  std::vector<Vec3d> x;
  std::vector<Hexahedron> hexahedra;
  {
    SceneUnderTest s;
    ASSERT_TRUE(s.load(beamScene("<MeshExporter filename=\"" + base +
                                 "\" format=\"ALL\" edges=\"0\" triangles=\"0\" quads=\"0\" "
                                 "exportAtEnd=\"1\"/>")))
        << describe(s.scene.log());
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(s.scene.step());
    x = s.positions();
    hexahedra = s.grid().hexahedra();
  }  // written when the scene closes
  for (const char* extension : {".vtu", ".vtk", ".msh"}) {
    SCOPED_TRACE(extension);
    const std::string loader =
        std::string(extension) == ".msh" ? "MeshGmshLoader" : "MeshVTKLoader";
    SceneUnderTest r;
    ASSERT_TRUE(r.load("<Node name=\"root\"><" + loader + " name=\"loader\" filename=\"" + base +
                       extension + "\"/></Node>"))
        << describe(r.scene.log());
    std::string why;
    const Base* object = resolveObjectPath(r.scene.root(), "@/loader", why);
    ASSERT_NE(object, nullptr) << why;
    const auto* position =
        dynamic_cast<const Data<std::vector<Vec3d>>*>(object->findData("position"));
    const auto* hexas =
        dynamic_cast<const Data<std::vector<Hexahedron>>*>(object->findData("hexahedra"));
    ASSERT_TRUE(position && hexas);
    EXPECT_EQ(position->value(), x);
    EXPECT_EQ(hexas->value(), hexahedra);
  }
  EXPECT_FALSE(fs::exists(base + ".ele")) << "TetGen's format written for hexahedra";
  std::string why;
  if (!meshioAvailable(why)) GTEST_SKIP() << why << " (Stroma's loaders read the files)";
  for (const char* extension : {".vtu", ".vtk", ".msh"}) {
    const MeshioMesh read = readWithMeshio(base + extension);
    ASSERT_EQ(read.points.size(), x.size()) << extension;
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(read.points[i][1], x[i].y()) << extension;
    EXPECT_EQ(read.cells.at("hexahedron").size(), hexahedra.size()) << extension;
  }
}

TEST(MeshExporter, NumbersItsFilesAsSofas) {
  // SOFA's MeshExporter.scn (exportEveryNumberOfSteps="5", 10 steps) writes outFile00001.vtk
  // and outFile00002.vtk (runSofa): the export's number on 5 digits.
  TempDir dir;
  const std::string base = (dir.path() / "outFile").string();
  SceneUnderTest s;
  ASSERT_TRUE(s.load(beamScene("<MeshExporter filename=\"" + base +
                               "\" format=\"vtk\" exportEveryNumberOfSteps=\"5\"/>")))
      << describe(s.scene.log());
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(s.scene.step());
  EXPECT_TRUE(fs::exists(base + "00001.vtk"));
  EXPECT_TRUE(fs::exists(base + "00002.vtk"));
  EXPECT_FALSE(fs::exists(base + "00003.vtk"));
  EXPECT_FALSE(fs::exists(base + ".vtk"));
}

TEST(MeshExporter, TetgenFilesReadBackThroughMeshio) {
  STROMA_SKIP_WITHOUT_MESHIO();
  TempDir dir;
  const std::string base = (dir.path() / "tets").string();
  SceneUnderTest s;
  ASSERT_TRUE(s.load(R"(<Node name="root"><Node name="Beam">
      <MeshTopology name="grid" tetrahedra="0 1 2 3  1 2 3 4"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  0.3 0.7 1.1"/>
      <MeshExporter filename=")" +
                     base + R"(" format="tetgen" exportAtBegin="1"/>
    </Node></Node>)"))
      << describe(s.scene.log());
  const MeshioMesh read = readWithMeshio(base + ".ele", "tetgen");
  ASSERT_EQ(read.points.size(), 5u);
  EXPECT_EQ(read.points[4][1], 0.7);
  EXPECT_EQ(read.cells.at("tetra"), (std::vector<std::vector<long>>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
}

// --- VisualModelOBJExporter ------------------------------------------------------------------

TEST(VisualModelOBJExporter, WritesTheVisualSurfacesAndTheirMaterials) {
  TempDir dir;
  const std::string base = (dir.path() / "visual").string();
  SceneUnderTest s;
  // A quad (split in two triangles by OglModel) moved by its translation, and a triangle.
  ASSERT_TRUE(s.load(R"(<Node name="root">
      <VisualModelOBJExporter filename=")" +
                     base + R"(" exportAtBegin="1"/>
      <Node name="Visual">
        <OglModel name="plate" position="0 0 0  1 0 0  1 1 0  0 1 0" quads="0 1 2 3"
                  translation="1 2 3" color="1 0 0 1"/>
        <OglModel name="flag" position="0 0 1  0.5 0 1  0 0.25 1" triangles="0 1 2"
                  color="0 0.5 1 0.25"/>
      </Node>
    </Node>)"))
      << describe(s.scene.log());
  std::string bytes, error;
  ASSERT_TRUE(meshio::readFileBytes(base + ".obj", bytes, error)) << error;
  MeshData read;
  ASSERT_TRUE(meshio::parseObj(bytes, {}, read, error)) << error;
  ASSERT_EQ(read.positions.size(), 7u);
  EXPECT_EQ(read.positions[2], Vec3d(2, 3, 3));  // (1 1 0) translated
  EXPECT_EQ(read.positions[5], Vec3d(0.5, 0, 1));
  ASSERT_EQ(read.triangles.size(), 3u);
  // The flag's triangle uses its own points, after the plate's four.
  EXPECT_EQ(read.triangles[2], (Triangle{4, 5, 6}));
  std::ifstream mtl(base + ".mtl");
  std::stringstream text;
  text << mtl.rdbuf();
  EXPECT_NE(text.str().find("newmtl plate\nKa"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("Kd 1 0 0"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("Kd 0 0.5 1"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("d 0.25"), std::string::npos) << text.str();
  EXPECT_NE(bytes.find("usemtl flag"), std::string::npos);
}

// --- Bad input -------------------------------------------------------------------------------

struct BadInput {
  const char* name;
  std::string component;  // written into the beam scene; "%DIR%" is a writable folder
  const char* field;      // the field the error names
  const char* needle;     // a piece of its text
};

// ctest lists the case by name, not as a byte dump of the struct.
void PrintTo(const BadInput& c, std::ostream* out) { *out << c.name; }

class ExportComponentBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ExportComponentBadInput, IsRefusedWithAMessageNamingTheField) {
  TempDir dir;
  std::string component = GetParam().component;
  for (std::size_t at; (at = component.find("%DIR%")) != std::string::npos;)
    component.replace(at, 5, dir.path().string());
  dir.write("bad.state", "T= 0\n  X= 0 0 0\nT= 0.01\n  X= 1 2 abc\n");
  dir.write("short.state", "T= 0\n  X= 0 0 0 1 1 1\n");
  SceneUnderTest s;
  EXPECT_FALSE(s.load(beamScene(component))) << component;
  bool found = false;
  for (const Message& m : errors(s.scene.log()))
    found = found ||
            (m.field == GetParam().field && m.text.find(GetParam().needle) != std::string::npos);
  EXPECT_TRUE(found) << "expected an error on '" << GetParam().field << "' with '"
                     << GetParam().needle << "'; got:\n"
                     << describe(s.scene.log());
}

const BadInput kBadInputs[] = {
    {"VTKExporterMissingFolder", R"(<VTKExporter filename="/nonexistent/folder/beam"/>)",
     "filename", "does not exist"},
    {"VTKExporterFolderIsAFile", R"(<VTKExporter filename="%DIR%/bad.state/beam"/>)", "filename",
     "does not exist"},
    {"VTKExporterUnknownField",
     R"(<VTKExporter filename="%DIR%/b" pointsDataFields="dofs.nothing"/>)", "pointsDataFields",
     "dofs.nothing"},
    {"VTKExporterNegativeEvery",
     R"(<VTKExporter filename="%DIR%/b" exportEveryNumberOfSteps="-2"/>)",
     "exportEveryNumberOfSteps", "-2"},
    {"MeshExporterUnknownFormat", R"(<MeshExporter filename="%DIR%/m" format="stl"/>)", "format",
     "stl"},
    {"MeshExporterNetgen", R"(<MeshExporter filename="%DIR%/m" format="netgen"/>)", "format",
     "not written"},
    {"MeshExporterNoFilename", R"(<MeshExporter format="vtk"/>)", "filename", "no file name"},
    {"OBJExporterMissingFolder", R"(<VisualModelOBJExporter filename="/nonexistent/x"/>)",
     "filename", "does not exist"},
    {"WriteStateNegativePeriod", R"(<WriteState filename="%DIR%/w" period="-0.1"/>)", "period",
     "-0.1"},
    {"WriteStateDofOutOfRange", R"(<WriteState filename="%DIR%/w" DOFsX="3 999"/>)", "DOFsX",
     "999"},
    {"WriteStateTimesGoBack", R"(<WriteState filename="%DIR%/w" time="0.2 0.1"/>)", "time",
     "increase"},
    {"WriteStateUnwritable", R"(<WriteState filename="/nonexistent/w.state"/>)", "filename",
     "does not exist"},
    {"ReadStateMissingFile", R"(<ReadState filename="%DIR%/missing.state"/>)", "filename",
     "missing.state"},
    {"ReadStateMalformedLine", R"(<ReadState filename="%DIR%/bad.state"/>)", "filename",
     "line 4: 'abc' is not a number"},
    {"ReadStateWrongCount", R"(<ReadState filename="%DIR%/short.state"/>)", "filename",
     "line 1 (T= 0"},
    {"ReadStateNegativeInterval", R"(<ReadState filename="%DIR%/short.state" interval="-1"/>)",
     "interval", "-1"},
};

INSTANTIATE_TEST_SUITE_P(Export, ExportComponentBadInput, ::testing::ValuesIn(kBadInputs),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace stroma::test
