// SPDX-License-Identifier: MIT
// SOFA's BoxROI_1d.scn and BoxROI_2d.scn (../shared/sofa/examples/Component/Engine/Select), run
// unmodified: a chain of points on a line (Vec1) and a grid in a plane (Vec2), clamped by a
// BoxROI at x = 0, hanging under gravity. They load, run 100 steps, the clamped points stay put,
// the bodies move the way gravity pulls them, and each moves exactly as the same scene made of
// 3D points (Vec3) does. A template no component has is still a clear error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/Node.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSofaDir = fs::path(STROMA_SHARED_DIR) / "sofa";
const fs::path kSelectDir = kSofaDir / "examples" / "Component" / "Engine" / "Select";

std::string readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Replaces the one occurrence of `from` in `text`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the scene";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Warnings allowed from these scenes: the CG's own report that it stopped on the scene's
/// `threshold` (p.Ap < 1e-9) before its relative `tolerance` (1e-9), which SOFA's CG does
/// silently. Any other warning fails.
bool isSolverStopReport(const Message& m) {
  return m.componentClass == "CGLinearSolver" &&
         (m.field == "threshold" || m.field == "iterations");
}

class SofaLowDimensionScenes : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::is_regular_file(kSelectDir / "BoxROI_1d.scn") ||
        !fs::is_regular_file(kSelectDir / "BoxROI_2d.scn"))
      GTEST_SKIP() << "SOFA's BoxROI_1d.scn and BoxROI_2d.scn are not in " << kSelectDir
                   << " (the shared test data lives beside the clone)";
    runtime.addDataDirectory(kSofaDir / "share");
  }

  /// Loads (a file, or its text with changes) and runs 100 steps; fails on any error, and on any
  /// warning but the CG's stop report.
  void run(Scene& scene, const fs::path& file, const std::string* text = nullptr) {
    const bool loaded = text ? scene.loadString(*text, file) : scene.loadFile(file);
    ASSERT_TRUE(loaded) << describe(scene.log());
    for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene.step()) << describe(scene.log());
    for (const Message& m : scene.log().messages()) {
      EXPECT_NE(m.level, MessageLevel::error) << formatForConsole(m);
      if (m.level == MessageLevel::warning && !isSolverStopReport(m))
        ADD_FAILURE() << "unexpected warning: " << formatForConsole(m);
    }
  }

  template <class DataTypes>
  MechanicalState<DataTypes>* bodyState(Scene& scene) {
    Node* body = scene.root().findChild("M1");
    auto* state = body ? body->get<MechanicalState<DataTypes>>() : nullptr;
    EXPECT_NE(state, nullptr) << "no " << DataTypes::name << " state in /root/M1";
    return state;
  }

  std::vector<unsigned> fixedIndices(Scene& scene) {
    std::vector<unsigned> indices;
    Node* body = scene.root().findChild("M1");
    Base* box = body ? body->findObject("box") : nullptr;
    BaseData* data = box ? box->findData("indices") : nullptr;
    EXPECT_NE(data, nullptr) << "no /root/M1/box.indices";
    if (data) {
      std::istringstream in(data->valueText());
      for (unsigned i; in >> i;) indices.push_back(i);
    }
    return indices;
  }

  Runtime runtime;
};

TEST_F(SofaLowDimensionScenes, ChainOnALineIsClampedAndStretchesAlongX) {
  // 21 points of 1 kg at x = 0..20, springs of ks = 500 N/m, gravity 9.81 along +x; the point
  // at x = 0 is clamped.
  Scene scene(runtime);
  run(scene, kSelectDir / "BoxROI_1d.scn");
  auto* state = bodyState<Vec1Types>(scene);
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(state->templateName(), "Vec1d");
  EXPECT_EQ(fixedIndices(scene), std::vector<unsigned>{0});
  const auto& x = state->readCoord(VecId::position());
  const auto& rest = state->readCoord(VecId::restPosition());
  ASSERT_EQ(x.size(), 21u);
  EXPECT_EQ(rest[20][0], 20.0) << "the grid's x coordinates";
  EXPECT_EQ(x[0][0], 0.0) << "the clamped point stays put";
  EXPECT_EQ(state->readDeriv(VecId::velocity())[0][0], 0.0);
  // Spring i (points i and i + 1) carries the weight of the 20 - i points below it; suddenly
  // loaded, a spring stretches by at most twice its static elongation (the undamped step
  // response), and it does stretch: every point is pulled along +x.
  double staticPosition = 0;
  for (int i = 1; i <= 20; ++i) {
    const double staticElongation = (21 - i) * 1.0 * 9.81 / 500;
    staticPosition += 1 + staticElongation;
    const double stretch = (x[i][0] - x[i - 1][0]) - 1;
    EXPECT_GT(stretch, 0) << "spring " << i - 1;
    EXPECT_LT(stretch, 2 * staticElongation) << "spring " << i - 1;
    EXPECT_GT(x[i][0], rest[i][0]) << "point " << i;
  }
  EXPECT_LT(x[20][0], 20 + 2 * (staticPosition - 20));
}

TEST_F(SofaLowDimensionScenes, GridInAPlaneIsClampedAndSagsUnderGravity) {
  // 21 x 5 points of 1 kg on [0, 20] x [0, 4], gravity "0 -9.81 1" of which a plane keeps
  // (0, -9.81); the 5 points at x = 0 are clamped.
  Scene scene(runtime);
  run(scene, kSelectDir / "BoxROI_2d.scn");
  auto* state = bodyState<Vec2Types>(scene);
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(state->templateName(), "Vec2d");
  EXPECT_EQ(fixedIndices(scene), (std::vector<unsigned>{0, 21, 42, 63, 84}));
  const auto& x = state->readCoord(VecId::position());
  const auto& rest = state->readCoord(VecId::restPosition());
  ASSERT_EQ(x.size(), 21u * 5);
  for (unsigned i : {0u, 21u, 42u, 63u, 84u}) EXPECT_EQ(x[i], rest[i]) << "clamped point " << i;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (i % 21 != 0) {
      EXPECT_LT(x[i].y(), rest[i].y()) << "point " << i << " sags";
    }
  EXPECT_LT(x[20].y(), rest[20].y() - 1) << "the free end falls by metres in 2 s";
}

// The low-dimensional states are the 3D scene restricted to a line or a plane: with the same
// gravity in that line or plane, the first coordinates follow the same motion, and the others
// stay 0 in 3D.
template <class DataTypes>
void expectSameMotionAsIn3D(Scene& reduced, Scene& full) {
  auto* a = reduced.root().findChild("M1")->get<MechanicalState<DataTypes>>();
  auto* b = full.root().findChild("M1")->get<MechanicalState<Vec3Types>>();
  ASSERT_TRUE(a && b);
  const auto& x = a->readCoord(VecId::position());
  const auto& y = b->readCoord(VecId::position());
  ASSERT_EQ(x.size(), y.size());
  constexpr int n = DataTypes::coordSize;
  double largest = 0, motion = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    largest = std::max(largest, (x[i] - y[i].template head<n>()).cwiseAbs().maxCoeff());
    largest = std::max(largest, y[i].template tail<3 - n>().cwiseAbs().maxCoeff());
    motion = std::max(motion, (x[i] - a->readCoord(VecId::restPosition())[i]).norm());
  }
  EXPECT_GT(motion, 1.0);
  // CG stops at the same small residual in both (threshold on p.Ap): the two runs agree to
  // round-off amplified over 100 steps, far below the metres of motion.
  EXPECT_LT(largest, 1e-9 * motion);
}

TEST_F(SofaLowDimensionScenes, ChainOnALineMovesAsTheSameChainOf3DPoints) {
  Scene line(runtime), space(runtime);
  const fs::path file = kSelectDir / "BoxROI_1d.scn";
  run(line, file);
  const std::string text = replaced(readFile(file), R"(template="Vec1")", R"(template="Vec3")");
  run(space, file, &text);
  expectSameMotionAsIn3D<Vec1Types>(line, space);
}

TEST_F(SofaLowDimensionScenes, GridInAPlaneMovesAsTheSameGridOf3DPoints) {
  Scene plane(runtime), space(runtime);
  const fs::path file = kSelectDir / "BoxROI_2d.scn";
  run(plane, file);
  // In 3D the gravity's z component would pull out of the plane: drop it, as the plane does.
  const std::string text =
      replaced(replaced(readFile(file), R"(template="Vec2")", R"(template="Vec3")"),
               R"(gravity="0 -9.81 1")", R"(gravity="0 -9.81 0")");
  run(space, file, &text);
  expectSameMotionAsIn3D<Vec2Types>(plane, space);
}

TEST_F(SofaLowDimensionScenes, AnUnknownTemplateListsTheAvailableOnes) {
  for (const char* component : {"MechanicalObject", "MeshSpringForceField", "BoxROI"}) {
    Scene scene(runtime);
    const std::string xml =
        std::string(R"(<Node name="root"><)") + component + R"( template="Vec4"/></Node>)";
    EXPECT_FALSE(scene.loadString(xml));
    const Message m = findError(scene.log(), "has no template 'Vec4'");
    EXPECT_EQ(m.field, "template") << describe(scene.log());
    EXPECT_EQ(m.componentClass, component);
    for (const char* available : {"'Vec1d'", "'Vec2d'", "'Vec3d'"})
      EXPECT_NE(m.text.find(available), std::string::npos) << m.text;
  }
}

}  // namespace
}  // namespace stroma::test
