// SPDX-License-Identifier: MIT
// PrecomputedLinearModel in scenes: forces and imposed displacements against the static solve
// of the same small-strain tetrahedra (TetrahedronFEMForceField method="small" + StaticSolver +
// SparseLDLSolver), the surface-only region, the disk cache (a second run loads it; corrupt,
// truncated and foreign files are refused and rewritten), and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "plugins/MeshIO/SceneFixture.h"
#include "plugins/SolidMechanics/FemTestScenes.h"
#include "simulation/MechanicalState.h"

namespace stroma::test {
namespace {

// The 4 x 1 x 1 m bar of 8 x 2 x 2 hexahedra cut into tetrahedra (81 nodes), clamped at x = 0.
const FemMesh& bar() {
  static const FemMesh mesh = makeBoxMesh(Vec3d(4, 1, 1), Vec3i(8, 2, 2));
  return mesh;
}

std::string clampedIndices() {
  std::string text;
  for (size_t i = 0; i < bar().points.size(); ++i)
    if (bar().points[i].x() == 0) text += std::to_string(i) + ' ';
  return text;
}

std::string fixed() {
  return "<FixedProjectiveConstraint indices=\"" + clampedIndices() + "\"/>\n";
}

class PrecomputedLinearModelTest : public SceneFixture {
 protected:
  std::string cache() { return write("bar.basis", "") + "x"; }  // a fresh path in the folder
  std::string model(const std::string& attributes) {
    return "<PrecomputedLinearModel name=\"model\" youngModulus=\"1e6\" poissonRatio=\"0.3\" " +
           attributes + "/>\n";
  }
  std::vector<Vec3d> positions(Scene& s) {
    auto* dofs = objectAt<MechanicalState<Vec3Types>>(s, "/body/dofs");
    return dofs ? dofs->readCoord(VecId::position()) : std::vector<Vec3d>{};
  }
  // Positions after one static step of the FEM scene with `loads`.
  std::vector<Vec3d> femSolution(const std::string& loads) {
    Runtime rt;
    Scene fem(rt);
    const std::string xml = femScene(
        bar(), "tetrahedra",
        "<StaticSolver newton_iterations=\"1\"/><SparseLDLSolver/>\n"
        "<TetrahedronFEMForceField method=\"small\" youngModulus=\"1e6\" poissonRatio=\"0.3\"/>\n" +
            fixed() + loads);
    if (!loadQuietly(fem, xml) || !fem.step()) return {};
    return positions(fem);
  }
  static double relativeError(const std::vector<Vec3d>& x, const std::vector<Vec3d>& reference) {
    double error = 0, norm = 0;
    for (size_t i = 0; i < reference.size(); ++i) {
      error += (x[i] - reference[i]).squaredNorm();
      norm += (reference[i] - bar().points[i]).squaredNorm();
    }
    return std::sqrt(error / norm);
  }
};

TEST_F(PrecomputedLinearModelTest, ForcesGiveTheStaticFemSolution) {
  const std::vector<std::string> loads{
      "<ConstantForceField indices=\"80\" forces=\"0 0 -300\"/>",
      "<ConstantForceField indices=\"80 44 71 26\" forces=\"0 0 -300  50 20 0  0 -100 40  "
      "10 10 10\"/>"};
  for (const std::string& load : loads) {
    Runtime rt;
    Scene s(rt);
    ASSERT_TRUE(loadQuietly(
        s, femScene(bar(), "tetrahedra", model("cacheFile=\"" + cache() + "\"") + fixed() + load)));
    ASSERT_TRUE(s.step());
    const auto reference = femSolution(load);
    ASSERT_EQ(reference.size(), bar().points.size());
    EXPECT_LT(relativeError(positions(s), reference), 1e-8) << load;
  }
}

TEST_F(PrecomputedLinearModelTest, ImposedDisplacementsFollowTheirKeyTimes) {
  // 20 nodes of the far half of the surface, pushed down by up to 2 cm over one second.
  std::string indices, atEnd, atStart;
  std::vector<unsigned> nodes;
  for (unsigned i = 0; i < bar().points.size() && nodes.size() < 20; ++i)
    if (bar().points[i].x() >= 2 && (bar().points[i].z() == 1 || bar().points[i].y() == 0)) {
      nodes.push_back(i);
      indices += std::to_string(i) + ' ';
      atStart += "0 0 0  ";
      atEnd += "0 0 -0.02  ";
    }
  ASSERT_EQ(nodes.size(), 20u);
  Runtime rt;
  Scene s(rt);
  ASSERT_TRUE(loadQuietly(
      s, femScene(bar(), "tetrahedra",
                  model("cacheFile=\"" + cache() + "\" imposedIndices=\"" + indices +
                        "\" keyTimes=\"0 1\" imposedDisplacements=\"" + atStart + atEnd + "\"") +
                      fixed(),
                  "gravity=\"0 0 0\" dt=\"0.25\"")));
  auto* model = objectAt<Base>(s, "/body/model");
  ASSERT_NE(model, nullptr);
  std::vector<Vec3d> reactionsAtHalf;
  for (int step = 1; step <= 4; ++step) {
    ASSERT_TRUE(s.step());
    const double expected = -0.02 * std::min(1.0, 0.25 * step);
    const auto x = positions(s);
    for (unsigned node : nodes)
      EXPECT_NEAR(x[node].z() - bar().points[node].z(), expected, 1e-12) << "node " << node;
    const auto& reactions =
        dynamic_cast<const Data<std::vector<Vec3d>>*>(model->findData("reactionForces"))->value();
    ASSERT_EQ(reactions.size(), 20u);
    if (step == 2) reactionsAtHalf = reactions;
    if (step == 4) {  // linear: the reactions double with the displacement
      for (size_t i = 0; i < 20; ++i) {
        EXPECT_LT((reactions[i] - 2 * reactionsAtHalf[i]).norm(),
                  1e-9 * reactions[i].norm() + 1e-9);
      }
    }
  }
  // The reactions push down: their sum is the force the imposed nodes take, negative in z.
  Vec3d total = Vec3d::Zero();
  for (const Vec3d& r : reactionsAtHalf) total += r;
  EXPECT_LT(total.z(), 0);
}

TEST_F(PrecomputedLinearModelTest, TheImposedSetCanChangeWhileRunning) {
  Runtime rt;
  Scene s(rt);
  ASSERT_TRUE(loadQuietly(s, femScene(bar(), "tetrahedra",
                                      model("useCache=\"false\" imposedIndices=\"80\" "
                                            "imposedDisplacements=\"0 0 -0.01\"") +
                                          fixed())));
  ASSERT_TRUE(s.step());
  EXPECT_NEAR(positions(s)[80].z() - 1, -0.01, 1e-12);
  // A tool grasping a second node: both reach their values.
  auto* model = objectAt<Base>(s, "/body/model");
  std::string error;
  ASSERT_TRUE(model->findData("imposedIndices")->read("80 44", error)) << error;
  ASSERT_TRUE(model->findData("imposedDisplacements")->read("0 0 -0.01  0.002 0 0", error));
  ASSERT_TRUE(s.step());
  EXPECT_NEAR(positions(s)[80].z() - 1, -0.01, 1e-12);
  EXPECT_NEAR(positions(s)[44].x() - bar().points[44].x(), 0.002, 1e-12);
  // A count that does not match: a warning naming the field, positions kept.
  const auto before = positions(s);
  ASSERT_TRUE(model->findData("imposedIndices")->read("80", error));
  ASSERT_TRUE(s.step());
  EXPECT_EQ(positions(s), before);
  bool warned = false;
  for (const Message& m : s.log().messages())
    warned = warned || (m.level == MessageLevel::warning && m.field == "imposedDisplacements");
  EXPECT_TRUE(warned);
}

TEST_F(PrecomputedLinearModelTest, SurfaceRegionMovesTheSurfaceAsTheWholeModel) {
  const std::string load = "<ConstantForceField indices=\"80\" forces=\"0 100 -300\"/>";
  Runtime rt1, rt2;
  Scene all(rt1), surface(rt2);
  ASSERT_TRUE(loadQuietly(
      all, femScene(bar(), "tetrahedra", model("useCache=\"false\"") + fixed() + load)));
  ASSERT_TRUE(loadQuietly(
      surface, femScene(bar(), "tetrahedra",
                        model("useCache=\"false\" deformedRegion=\"surface\"") + fixed() + load)));
  ASSERT_TRUE(all.step());
  ASSERT_TRUE(surface.step());
  const auto xAll = positions(all), xSurface = positions(surface);
  int interior = 0;
  for (size_t i = 0; i < xAll.size(); ++i) {
    const Vec3d& p = bar().points[i];
    const bool onSurface =
        p.x() == 0 || p.x() == 4 || p.y() == 0 || p.y() == 1 || p.z() == 0 || p.z() == 1;
    if (onSurface) {
      EXPECT_LT((xSurface[i] - xAll[i]).norm(), 1e-14 * (xAll[80] - bar().points[80]).norm());
    } else {
      EXPECT_EQ(xSurface[i], p) << "interior node " << i << " stays at rest";
      ++interior;
    }
  }
  EXPECT_EQ(interior, 7);
}

// The model's output Data as text (loadedFromCache...).
std::string outputOf(Scene& s, const char* field) {
  auto* model = objectAt<Base>(s, "/body/model");
  return model && model->findData(field) ? model->findData(field)->valueText() : "";
}

TEST_F(PrecomputedLinearModelTest, SecondRunLoadsTheCacheAndBadFilesAreRecomputed) {
  const std::string path = cache();
  const std::string load = "<ConstantForceField indices=\"80\" forces=\"0 0 -300\"/>";
  const std::string xml =
      femScene(bar(), "tetrahedra", model("cacheFile=\"" + path + "\"") + fixed() + load);
  std::vector<Vec3d> computed;
  {
    Runtime rt;
    Scene s(rt);
    ASSERT_TRUE(loadQuietly(s, xml));
    EXPECT_EQ(outputOf(s, "loadedFromCache"), "0");
    ASSERT_TRUE(s.step());
    computed = positions(s);
  }
  ASSERT_TRUE(std::filesystem::exists(path));
  const auto size = std::filesystem::file_size(path);
  {
    Runtime rt;
    Scene s(rt);
    ASSERT_TRUE(loadQuietly(s, xml));
    EXPECT_EQ(outputOf(s, "loadedFromCache"), "1");
    EXPECT_EQ(outputOf(s, "precomputationTime"), "0");
    ASSERT_TRUE(s.step());
    EXPECT_EQ(positions(s), computed);
  }
  // A flipped byte in the payload, a truncated file, a file of another material: each is
  // refused with its reason, the basis is recomputed (same answer) and the file rewritten.
  auto damage = [&](const std::string& how) {
    if (how == "corrupt") {
      std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
      f.seekp(std::streamoff(size / 2));
      f.put('\x5a');
    } else if (how == "truncated") {
      std::filesystem::resize_file(path, size - 100);
    }
  };
  for (const std::string& how : std::vector<std::string>{"corrupt", "truncated"}) {
    damage(how);
    Runtime rt;
    Scene s(rt);
    ASSERT_TRUE(s.loadString(xml)) << how;
    const Message warning = [&] {
      for (const Message& m : s.log().messages())
        if (m.level == MessageLevel::warning) return m;
      return Message{};
    }();
    EXPECT_NE(warning.text.find(how), std::string::npos) << how << ": " << warning.text;
    EXPECT_EQ(outputOf(s, "loadedFromCache"), "0") << how;
    ASSERT_TRUE(s.step());
    EXPECT_EQ(positions(s), computed) << how;
    EXPECT_EQ(std::filesystem::file_size(path), size) << how << ": rewritten";
  }
  {  // the same file for another material: the key differs
    Runtime rt;
    Scene s(rt);
    std::string other = xml;
    other.replace(other.find("youngModulus=\"1e6\""), 18, "youngModulus=\"2e6\"");
    ASSERT_TRUE(s.loadString(other));
    bool foreign = false;
    for (const Message& m : s.log().messages())
      foreign = foreign || m.text.find("another mesh") != std::string::npos;
    EXPECT_TRUE(foreign);
    EXPECT_EQ(outputOf(s, "loadedFromCache"), "0");
    ASSERT_TRUE(s.step());
    const auto x = positions(s);  // twice as stiff: half the displacement
    EXPECT_NEAR(x[80].z() - 1, 0.5 * (computed[80].z() - 1), 1e-12);
  }
}

TEST_F(PrecomputedLinearModelTest, BadInputIsReportedWithoutACrash) {
  struct Case {
    std::string components;
    std::string field;
  };
  const std::vector<Case> cases{
      {model("useCache=\"false\""), "fixedIndices"},  // nothing fixed: singular
      {"<PrecomputedLinearModel useCache=\"false\" poissonRatio=\"0.5\"/>" + fixed(),
       "poissonRatio"},
      {model("useCache=\"false\" imposedIndices=\"40\" imposedDisplacements=\"0 0 0\"") + fixed(),
       "imposedIndices"},  // node 40 is inside the bar
      {model("useCache=\"false\" imposedIndices=\"80\" imposedDisplacements=\"0 0 0 1 1 1\"") +
           fixed(),
       "imposedDisplacements"},
      {model("useCache=\"false\" fixedIndices=\"0 500\""), "fixedIndices"},
      // a single clamped node leaves the rotations free: singular
      {model("useCache=\"false\" fixedIndices=\"0\""), "fixedIndices"},
  };
  for (const Case& c : cases) {
    Runtime rt;
    Scene s(rt);
    EXPECT_FALSE(s.loadString(femScene(bar(), "tetrahedra", c.components))) << c.components;
    bool named = false;
    std::string all;
    for (const Message& m : s.log().messages()) {
      all += m.text + '\n';
      named = named || (m.level == MessageLevel::error && m.field == c.field);
    }
    EXPECT_TRUE(named) << c.field << " not named in:\n" << all;
  }
}

}  // namespace
}  // namespace stroma::test
