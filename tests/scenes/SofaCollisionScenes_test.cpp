// SPDX-License-Identifier: MIT
// The SOFA scenes of ../shared/sofa/examples with a collision pipeline that Stroma runs (listed
// in sofa-collision-scenes.txt, beside this file) load and run 100 steps unmodified, without an
// error and with finite states, so that none of them silently stops running. Among them
// Demos/liver.scn. Skipped, with a message, without ../shared or without the Collision plugin
// (a build without Bullet).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSofaDir = fs::path(STROMA_SHARED_DIR) / "sofa";

std::vector<std::string> collisionScenes() {
  std::vector<std::string> scenes;
  std::ifstream in(fs::path(STROMA_SOURCE_DIR) / "tests/scenes/sofa-collision-scenes.txt");
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') scenes.push_back(line);
  return scenes;
}

bool allFinite(const Node& node) {
  for (const auto& o : node.objects())
    if (const auto* state = dynamic_cast<const BaseMechanicalState*>(o.get())) {
      std::size_t where = 0;
      if (!std::isfinite(state->vMaxAbs(VecId::position(), where)) ||
          !std::isfinite(state->vMaxAbs(VecId::velocity(), where)))
        return false;
    }
  for (const auto& c : node.children())
    if (!allFinite(*c)) return false;
  return true;
}

TEST(SofaCollisionScenes, EachRuns100StepsWithoutError) {
  if (!fs::is_directory(kSofaDir / "examples"))
    GTEST_SKIP() << "SOFA's scenes are not at " << kSofaDir
                 << " (the shared test data lives beside the clone)";
  Runtime runtime;
  for (const auto& entry : runtime.plugins().available())
    if (entry.name == "Collision" && !entry.unavailable.empty())
      GTEST_SKIP() << "this build left the Collision plugin out: " << entry.unavailable;
  runtime.addDataDirectory(kSofaDir / "share");
  runtime.addDataDirectory(kSofaDir / "examples");
  const std::vector<std::string> scenes = collisionScenes();
  ASSERT_GE(scenes.size(), 30u);
  EXPECT_NE(std::find(scenes.begin(), scenes.end(), "examples/Demos/liver.scn"), scenes.end());
  int passed = 0;
  for (const std::string& name : scenes) {
    SCOPED_TRACE(name);
    Scene scene(runtime);
    scene.setThreadCount(1);
    if (!scene.loadFile(kSofaDir / name)) {
      ADD_FAILURE() << "does not load:\n" << describe(scene.log());
      continue;
    }
    bool stepped = true;
    for (int i = 0; i < 100 && stepped; ++i) stepped = scene.step();
    EXPECT_TRUE(stepped) << describe(scene.log());
    EXPECT_EQ(scene.log().runFailureCount(), 0u) << describe(scene.log());
    const bool finite = allFinite(scene.root());
    EXPECT_TRUE(finite);
    passed += stepped && finite && scene.log().runFailureCount() == 0;
  }
  std::printf("[ collision] %d of %zu SOFA scenes with a collision pipeline ran 100 steps\n",
              passed, scenes.size());
}

}  // namespace
}  // namespace stroma::test
