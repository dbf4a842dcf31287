// SPDX-License-Identifier: MIT
// ReferenceComparison with reference files: a state file matched by index, marker files
// matched by index and located in the mesh (the Truth Cube beads), and bad input: errors that
// name the field, the file and the line, never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ValidationScenes.h"
#include "simulation/AnimationLoop.h"
#include "simulation/StateFile.h"

namespace stroma::test {
namespace {

std::string cubeScene(const FemMesh& mesh, const std::string& compare) {
  return bodyScene(mesh, "hexahedra", mesh.points, compare);
}

std::string writeFile(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

/// Moves every point of the state by the affine map x -> x + A x, then lets the comparison
/// see the new state (as at the start of a step).
void deform(Scene& scene, const Mat3d& A) {
  for (Vec3d& x :
       objectAt<MechanicalState<Vec3Types>>(scene, "/body/dofs")->writeCoord(VecId::position()))
    x += A * x;
  objectAt<BehaviorModel>(scene, "/body/compare")->updatePosition(1);
}

/// Errors of a scene that must not load; returns the messages.
std::string loadErrors(const std::string& xml) {
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString(xml));
  std::string messages;
  for (const Message& m : scene.log().messages())
    if (m.level == MessageLevel::error) messages += formatForConsole(m) + '\n';
  return messages;
}

const Mat3d kStretch = (Mat3d() << 0.02, 0.01, 0, 0, -0.01, 0, 0.005, 0, 0.03).finished();

TEST(ReferenceFiles, StateFileByIndex) {
  const FemMesh mesh = makeBoxMesh(Vec3d(1, 1, 1), Vec3i(2, 2, 2));
  // The reference: the cube deformed by kStretch, written as `stroma run --export-state` does.
  std::string file;
  {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, cubeScene(mesh, "")));
    for (Vec3d& x :
         objectAt<MechanicalState<Vec3Types>>(scene, "/body/dofs")->writeCoord(VecId::position()))
      x += kStretch * x;
    std::ostringstream out;
    writeStateHeader(out);
    writeSnapshot(out, captureState(scene.root(), 1));
    file = writeFile("stroma_reference_by_index.state", out.str());
  }
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, cubeScene(mesh,
                                           "<ReferenceComparison name=\"compare\" "
                                           "referenceState=\"" +
                                               file + "\" referenceLength=\"0.5\"/>")));
  // At rest the error is the reference's own displacement; deformed alike, none.
  double largest = 0;
  for (const Vec3d& p : mesh.points) largest = std::max(largest, (kStretch * p).norm());
  EXPECT_NEAR(comparisonOutput(scene, "maxErrorAbsolute"), largest, 1e-15);
  EXPECT_NEAR(comparisonOutput(scene, "maxError"), largest / 0.5, 1e-15);
  deform(scene, kStretch);
  EXPECT_LT(comparisonOutput(scene, "maxErrorAbsolute"), 1e-15);
}

TEST(ReferenceFiles, MarkersByIndexAndLocatedInTheMesh) {
  const FemMesh mesh = makeBoxMesh(Vec3d(1, 1, 1), Vec3i(2, 2, 2));
  // Markers inside the cube (x0, y0, z0 at rest, then x1, y1, z1 deformed by kStretch), in mm,
  // with a header line and a comment.
  const std::vector<Vec3d> rest = {{0.1, 0.2, 0.3}, {0.5, 0.5, 0.5}, {0.9, 0.35, 0.75}};
  std::string csv = "# test markers\nname,x0,y0,z0,x1,y1,z1\n";
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const Vec3d p = 1e3 * rest[i], q = 1e3 * (rest[i] + kStretch * rest[i]);
    csv += std::to_string(i) + "," + std::to_string(p.x()) + ", " + std::to_string(p.y()) + "," +
           std::to_string(p.z()) + "," + std::to_string(q.x()) + "," + std::to_string(q.y()) + "," +
           std::to_string(q.z()) + "\n";
  }
  const std::string file = writeFile("stroma_markers.csv", csv);
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, cubeScene(mesh,
                                           "<ReferenceComparison name=\"compare\" "
                                           "markers=\"" +
                                               file +
                                               "\" markerColumns=\"4 5 6\" "
                                               "restMarkerColumns=\"1 2 3\" "
                                               "markerScale=\"1e-3\" "
                                               "referenceLength=\"1\"/>")));
  // The mesh interpolates an affine field exactly: deformed by kStretch, no error (to the 6
  // decimals of the file, in mm).
  deform(scene, kStretch);
  EXPECT_LT(comparisonOutput(scene, "maxErrorAbsolute"), 2e-9);
  // By index: the cube's centre (point 13 of the 3 x 3 x 3 points) as marker 1 of a file.
  const std::string centre = writeFile("stroma_marker_centre.csv", "0.5,0.5,0.5\n0.5,0.5,0.6\n");
  Runtime runtime2;
  Scene byIndex(runtime2);
  ASSERT_TRUE(loadQuietly(byIndex, cubeScene(mesh,
                                             "<ReferenceComparison name=\"compare\" "
                                             "markers=\"" +
                                                 centre +
                                                 "\" markerIndices=\"13 13\" "
                                                 "referenceLength=\"2\"/>")));
  EXPECT_NEAR(comparisonOutput(byIndex, "maxErrorAbsolute"), 0.1, 1e-15);
  EXPECT_NEAR(comparisonOutput(byIndex, "rmsErrorAbsolute"), 0.1 / std::sqrt(2.0), 1e-15);
  EXPECT_EQ(comparisonOutput(byIndex, "worstIndex"), 1);
}

TEST(ReferenceFiles, TruthCubeBeadsAtRest) {
  const std::filesystem::path file =
      std::filesystem::path(STROMA_SHARED_DIR) / "data/truthcube/uniaxial_positions.csv";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file << " (../shared absent)";
  // The 80 mm cube around the beads' centre, undeformed: the errors are the beads' measured
  // displacements at 5 % strain, computed here from the file directly.
  std::ifstream in(file);
  std::string line;
  std::vector<double> moved;
  Vec3d centre = Vec3d::Zero();
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'i') continue;
    std::vector<double> v;
    std::stringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
    moved.push_back(1e-3 * (Vec3d(v[6], v[7], v[8]) - Vec3d(v[3], v[4], v[5])).norm());
    centre += 1e-3 * Vec3d(v[3], v[4], v[5]);
  }
  ASSERT_EQ(moved.size(), 343u);
  centre /= 343.0;
  FemMesh mesh = makeBoxMesh(Vec3d(0.08, 0.08, 0.08), Vec3i(4, 4, 4));
  for (Vec3d& p : mesh.points) p += centre - Vec3d::Constant(0.04);
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, cubeScene(mesh,
                                           "<ReferenceComparison name=\"compare\" "
                                           "markers=\"" +
                                               file.string() +
                                               "\" markerColumns=\"6 7 8\" "
                                               "restMarkerColumns=\"3 4 5\" "
                                               "markerScale=\"1e-3\" "
                                               "referenceLength=\"0.08\"/>")));
  double largest = 0, squares = 0;
  for (double d : moved) {
    largest = std::max(largest, d);
    squares += d * d;
  }
  EXPECT_NEAR(comparisonOutput(scene, "maxErrorAbsolute"), largest, 1e-12);
  EXPECT_NEAR(comparisonOutput(scene, "rmsErrorAbsolute"), std::sqrt(squares / 343), 1e-12);
}

TEST(ReferenceFiles, BadInputIsAnErrorNamingTheFieldAndFile) {
  const FemMesh mesh = makeBoxMesh(Vec3d(1, 1, 1), Vec3i(1, 1, 1));
  const auto scene = [&](const std::string& attributes) {
    return cubeScene(mesh, "<ReferenceComparison name=\"compare\" " + attributes + "/>");
  };
  std::string e = loadErrors(scene("analytic=\"patch\" referenceLength=\"0\""));
  EXPECT_NE(e.find("referenceLength"), std::string::npos) << e;
  e = loadErrors(scene("referenceLength=\"1\""));
  EXPECT_NE(e.find("no reference given"), std::string::npos) << e;
  e = loadErrors(scene("analytic=\"patch\" markers=\"m.csv\" referenceLength=\"1\""));
  EXPECT_NE(e.find("several references"), std::string::npos) << e;
  e =
      loadErrors(scene("markers=\"/nonexistent/markers.csv\" markerIndices=\"0\" "
                       "referenceLength=\"1\""));
  EXPECT_NE(e.find("/nonexistent/markers.csv"), std::string::npos) << e;
  EXPECT_NE(e.find("markers"), std::string::npos) << e;
  // A NaN on line 3, a short line on line 2.
  const std::string nan = writeFile("stroma_markers_nan.csv", "# x,y,z\n0,0,0\n1,nan,0\n");
  e = loadErrors(scene("markers=\"" + nan + "\" markerIndices=\"0 1\" referenceLength=\"1\""));
  EXPECT_NE(e.find(nan + ":3:"), std::string::npos) << e;
  const std::string shortLine = writeFile("stroma_markers_short.csv", "0,0,0\n1,2\n");
  e = loadErrors(
      scene("markers=\"" + shortLine + "\" markerIndices=\"0 1\" referenceLength=\"1\""));
  EXPECT_NE(e.find(shortLine + ":2:"), std::string::npos) << e;
  const std::string two = writeFile("stroma_markers_two.csv", "0,0,0\n1,1,1\n");
  e = loadErrors(scene("markers=\"" + two + "\" markerIndices=\"0\" referenceLength=\"1\""));
  EXPECT_NE(e.find("markerIndices"), std::string::npos) << e;
  // A state file with another count and no rest snapshot; a malformed one.
  const std::string other = writeFile(
      "stroma_reference_other.state",
      "# stroma-state 1\nsnapshot time 1 step 1\nstate /x Vec3d 1 3 3\n0 0 0 0 0 0\nend\n");
  e = loadErrors(scene("referenceState=\"" + other + "\" referenceLength=\"1\""));
  EXPECT_NE(e.find("step 0"), std::string::npos) << e;
  const std::string broken = writeFile("stroma_reference_broken.state",
                                       "# stroma-state 1\nsnapshot time 1 step 1\nstate /x Vec3d 2 "
                                       "3 3\n0 0 0 0 0 0\nend\n");
  e = loadErrors(scene("referenceState=\"" + broken + "\" referenceLength=\"1\""));
  EXPECT_NE(e.find("referenceState"), std::string::npos) << e;
  EXPECT_NE(e.find("line"), std::string::npos) << e;
  e = loadErrors(scene("analytic=\"patch\" indices=\"8\" referenceLength=\"1\""));
  EXPECT_NE(e.find("indices"), std::string::npos) << e;
  e = loadErrors(scene("analytic=\"cantileverTip\" length=\"3\" referenceLength=\"1\""));
  EXPECT_NE(e.find("free end"), std::string::npos) << e;
  e = loadErrors(scene("analytic=\"lame\" innerRadius=\"2\" referenceLength=\"1\""));
  EXPECT_NE(e.find("innerRadius"), std::string::npos) << e;
}

}  // namespace
}  // namespace stroma::test
