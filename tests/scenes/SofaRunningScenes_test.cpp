// SPDX-License-Identifier: MIT
// Every SOFA example scene of ../shared/sofa that runs 100 steps with `stroma run`, listed in
// sofa-running-scenes.txt (beside this file, written by scripts/sofa-corpus.py --write-list),
// still loads unmodified without an error and runs 10 steps without a failed step or a
// diverged state, its positions and velocities finite: so that none silently stops running.
// One test a scene (ctest spreads them over the cores). Skipped, with a message, without
// ../shared, or for a scene that uses a plugin this build left out (a library was missing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "scenes/SceneLists.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSofaDir = SofaScenesFixture::kSofaDir;
constexpr int kSteps = 10;

std::vector<std::string> runningScenes() {
  return readSceneList(fs::path(STROMA_SOURCE_DIR) / "tests/scenes/sofa-running-scenes.txt");
}

/// The first mechanical state with a position or velocity that is not finite, else empty.
std::string firstNotFinite(const Node& node) {
  for (const auto& o : node.objects())
    if (const auto* state = dynamic_cast<const BaseMechanicalState*>(o.get())) {
      std::size_t where = 0;
      if (!std::isfinite(state->vMaxAbs(VecId::position(), where)) ||
          !std::isfinite(state->vMaxAbs(VecId::velocity(), where)))
        return o->name();
    }
  for (const auto& c : node.children())
    if (std::string name = firstNotFinite(*c); !name.empty()) return name;
  return {};
}

/// Why the scene could not be created when it names a component of a plugin that this build
/// left out, else empty.
std::string leftOutPluginUsed(Runtime& runtime, const MessageLog& log) {
  for (const auto& entry : runtime.plugins().available()) {
    if (entry.unavailable.empty()) continue;
    const std::string said = "is in plugin " + entry.name + ", which this build left out";
    for (const Message& m : errors(log))
      if (m.text.find(said) != std::string::npos)
        return "it uses " + m.componentClass + ", of the plugin " + entry.name +
               " that this build left out: " + pluginLeftOut(runtime, entry.name);
  }
  return {};
}

class SofaRunningScenes : public ::testing::TestWithParam<std::string>,
                          protected SofaScenesFixture {
 protected:
  void SetUp() override {
    if (!enterSofaFolder("sofa-running"))
      GTEST_SKIP() << "SOFA's scenes are not at " << kSofaDir
                   << " (the shared test data lives beside the clone)";
  }
  void TearDown() override { leaveSofaFolder(); }
};

TEST_P(SofaRunningScenes, LoadsAndRunsWithoutError) {
  Scene scene(runtime);
  scene.setThreadCount(1);
  if (!scene.loadFile(kSofaDir / GetParam())) {
    if (const std::string why = leftOutPluginUsed(runtime, scene.log()); !why.empty())
      GTEST_SKIP() << GetParam() << ": " << why;
    FAIL() << GetParam() << " does not load:\n" << describe(scene.log());
  }
  for (int i = 0; i < kSteps; ++i)
    ASSERT_TRUE(scene.step()) << "step " << i + 1 << " failed:\n" << describe(scene.log());
  EXPECT_EQ(scene.log().runFailureCount(), 0u) << describe(scene.log());
  EXPECT_EQ(firstNotFinite(scene.root()), "") << "a state is not finite after " << kSteps
                                              << " steps";
}

/// "examples/Demos/liver.scn" -> "Demos_liver": a test name (letters, digits and '_').
std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string path = info.param;
  if (path.rfind("examples/", 0) == 0) path.erase(0, 9);
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".scn") == 0) path.resize(path.size() - 4);
  std::string name;
  for (char c : path) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Sofa, SofaRunningScenes, ::testing::ValuesIn(runningScenes()), testName);

TEST(SofaRunningScenesList, HoldsTheScenesOfTheOtherLists) {
  // The collision and free-motion lists name scenes that run 100 steps: this list has them.
  const std::vector<std::string> running = runningScenes();
  ASSERT_GE(running.size(), 100u);
  for (const char* other : {"sofa-collision-scenes.txt", "sofa-freemotion-scenes.txt"})
    for (const std::string& scene :
         readSceneList(fs::path(STROMA_SOURCE_DIR) / "tests/scenes" / other))
      EXPECT_NE(std::find(running.begin(), running.end(), scene), running.end())
          << scene << " (" << other << ") is not in sofa-running-scenes.txt";
}

}  // namespace
}  // namespace stroma::test
