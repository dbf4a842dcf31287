// SPDX-License-Identifier: MIT
// `stroma run SCENE --export-vtk DIR`, run as a user runs it: the VTU files give back, through
// meshio (skipped when absent), the positions and velocities of the same run's --export-state
// file to the last bit, the displacement from the initial state, the von Mises stress of the
// scene's StressField; the .pvd lists the files and times; a batch run never loads the Export
// plugin; a folder that cannot be made is refused.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "MeshioReader.h"
#include "core/PathResolver.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Scene.h"
#include "simulation/StateFile.h"
#include "simulation/StressField.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kBeam = R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <Node name="Beam">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="100" tolerance="1e-12" threshold="1e-16"/>
    <RegularGridTopology name="grid" nx="3" ny="3" nz="5" xmin="0" xmax="2" ymin="0" ymax="2"
                         zmin="0" zmax="4"/>
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="10"/>
    <HexahedronFEMForceField name="fem" youngModulus="2000" poissonRatio="0.3"/>
    <FixedProjectiveConstraint indices="0 1 2 3 4 5 6 7 8"/>
  </Node>
</Node>
)";

TEST(RunExportVtk, FilesGiveBackTheRunsStatesAndStress) {
  STROMA_SKIP_WITHOUT_MESHIO();
  TempDir dir;
  const fs::path scene = dir.write("beam.scn", kBeam);
  const fs::path out = dir.path() / "vtk", stateFile = dir.path() / "state.txt";
  const CliRun run =
      runCli(STROMA_CLI, "run \"" + scene.string() + "\" -n 4 --export-every 2 --export-vtk \"" +
                             out.string() + "\" --export-state \"" + stateFile.string() + "\"");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("exportVtk"), std::string::npos) << "the phase in the timing";

  std::ifstream in(stateFile);
  std::vector<StateSnapshot> snapshots;
  std::string error;
  ASSERT_TRUE(readStateFile(in, snapshots, error)) << error;
  ASSERT_EQ(snapshots.size(), 3u);  // steps 0, 2, 4
  const StateRecord& initial = snapshots[0].states.at(0);
  ASSERT_EQ(initial.path, "/root/Beam/dofs");

  for (const StateSnapshot& snapshot : snapshots) {
    char name[64];
    std::snprintf(name, sizeof name, "root_Beam_dofs_%06lld.vtu", snapshot.step);
    SCOPED_TRACE(name);
    const MeshioMesh read = readWithMeshio(out / name);
    const StateRecord& state = snapshot.states.at(0);
    ASSERT_EQ(read.points.size(), state.count());
    for (std::size_t i = 0; i < state.count(); ++i)
      for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(read.points[i][a], state.positions[3 * i + a]);
        EXPECT_EQ(read.pointData.at("velocity")[3 * i + a], state.velocities[3 * i + a]);
        EXPECT_EQ(read.pointData.at("displacement")[3 * i + a],
                  state.positions[3 * i + a] - initial.positions[3 * i + a]);
      }
    EXPECT_EQ(read.cells.at("hexahedron").size(), 16u);  // 2 x 2 x 4
    EXPECT_EQ(read.pointData.at("vonMises").size(), state.count());
    EXPECT_EQ(read.cellData.at("vonMises").size(), 16u);
  }

  // The stress is the scene's own StressField at the same state (the same run in process: the
  // results do not depend on the thread count).
  Runtime runtime;
  useTestPlugins(runtime);
  Scene same(runtime);
  ASSERT_TRUE(same.loadFile(scene)) << describe(same.log());
  for (int k = 0; k < 4; ++k) ASSERT_TRUE(same.step());
  std::string why;
  const auto* field =
      dynamic_cast<const StressField*>(resolveObjectPath(same.root(), "@/Beam/fem", why));
  ASSERT_NE(field, nullptr) << why;
  std::vector<double> perPoint, perElement;
  ASSERT_TRUE(field->vonMisesPerPoint(perPoint) && field->vonMisesPerElement(perElement));
  const MeshioMesh last = readWithMeshio(out / "root_Beam_dofs_000004.vtu");
  EXPECT_EQ(last.pointData.at("vonMises"), perPoint);
  EXPECT_EQ(last.cellData.at("vonMises"), perElement);
  EXPECT_GT(*std::max_element(perElement.begin(), perElement.end()), 0.1);  // the beam bends

  // The collection: one data set per exported step, with the state file's times.
  const CliRun pvd =
      runCli("/usr/bin/python3",
             "-c \"import sys, xml.etree.ElementTree as E; [print(repr(float(d.get('timestep'))) + "
             "'|' + d.get('file')) for d in E.parse(sys.argv[1]).iter('DataSet')]\" \"" +
                 (out / "root_Beam_dofs.pvd").string() + "\"");
  ASSERT_EQ(pvd.exitCode, 0) << pvd.output;
  std::istringstream lines(pvd.output);
  std::string line;
  for (const StateSnapshot& snapshot : snapshots) {
    ASSERT_TRUE(std::getline(lines, line));
    char name[64];
    std::snprintf(name, sizeof name, "root_Beam_dofs_%06lld.vtu", snapshot.step);
    EXPECT_EQ(std::stod(line.substr(0, line.find('|'))), snapshot.time);
    EXPECT_EQ(line.substr(line.find('|') + 1), name);
  }
  EXPECT_FALSE(std::getline(lines, line)) << "extra data set " << line;
}

TEST(RunExportVtk, BatchRunsNeverLoadTheExportPlugin) {
  TempDir dir;
  const fs::path scene = dir.write("beam.scn", kBeam);
  const CliRun check = runCli(STROMA_CLI, "check \"" + scene.string() + "\"");
  ASSERT_EQ(check.exitCode, 0) << check.output;
  ASSERT_NE(check.output.find("plugins loaded:"), std::string::npos) << check.output;
  EXPECT_EQ(check.output.find("Export"), std::string::npos) << check.output;
  // A scene with one of its components does load it (the check above can see it).
  std::string withExporter = kBeam;
  withExporter.insert(withExporter.find("  </Node>"),
                      "    <MeshExporter filename=\"" + (dir.path() / "m").string() + "\"/>\n");
  const fs::path exporting = dir.write("exporting.scn", withExporter);
  const CliRun loaded = runCli(STROMA_CLI, "check \"" + exporting.string() + "\"");
  ASSERT_EQ(loaded.exitCode, 0) << loaded.output;
  EXPECT_NE(loaded.output.find("Export"), std::string::npos) << loaded.output;
}

TEST(RunExportVtk, AFolderThatCannotBeMadeIsRefused) {
  TempDir dir;
  const fs::path scene = dir.write("beam.scn", kBeam);
  const CliRun run = runCli(STROMA_CLI, "run \"" + scene.string() + "\" -n 2 --export-vtk \"" +
                                            scene.string() + "/vtk\"");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--export-vtk: cannot make the folder"), std::string::npos)
      << run.output;
  const CliRun zero = runCli(STROMA_CLI, "run \"" + scene.string() + "\" -n 2 --export-vtk \"" +
                                             (dir.path() / "v").string() + "\" --export-every 0");
  EXPECT_EQ(zero.exitCode, 2) << zero.output;
}

}  // namespace
}  // namespace stroma::test
