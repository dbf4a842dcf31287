// SPDX-License-Identifier: MIT
// Every scene shipped in scenes/ loads and runs 100 steps without an error or a warning. Scenes are
// found at run time, so a new scene is tested as soon as it is added; files under a fragments/
// folder are pieces for <include>, not scenes. A scene that needs a plugin this build left out (a
// library it needs was missing, e.g. Bullet for scenes/collision) is skipped, and said so.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> bundledScenes() {
  std::vector<fs::path> scenes;
  const fs::path root = fs::path(STROMA_SOURCE_DIR) / "scenes";
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    if (it->is_directory() && it->path().filename() == "fragments") {
      it.disable_recursion_pending();
      continue;
    }
    const std::string extension = it->path().extension().string();
    // A URDF robot is a scene by itself (Scene::loadFile wraps it in a default scene).
    if (it->is_regular_file() &&
        (extension == ".scn" || extension == ".xml" || extension == ".urdf"))
      scenes.push_back(it->path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(BundledScenes, EverySceneRuns100StepsWithoutErrorOrWarning) {
  const std::vector<fs::path> scenes = bundledScenes();
  ASSERT_FALSE(scenes.empty()) << "no scene found under " << STROMA_SOURCE_DIR << "/scenes";
  constexpr int kSteps = 100;
  int passed = 0, skipped = 0;
  for (const fs::path& file : scenes) {
    SCOPED_TRACE(file.string());
    Runtime runtime;
    Scene scene(runtime);
    if (!scene.loadFile(file)) {
      const Message leftOut = findError(scene.log(), "which this build left out");
      if (!leftOut.text.empty()) {
        std::printf("[ skipped  ] %s: %s\n", file.string().c_str(), leftOut.text.c_str());
        ++skipped;
        continue;
      }
      ADD_FAILURE() << "does not load:\n" << describe(scene.log());
      continue;
    }
    bool stepped = true;
    for (int i = 0; i < kSteps && stepped; ++i) stepped = scene.step();
    EXPECT_TRUE(stepped) << describe(scene.log());
    EXPECT_EQ(scene.log().errorCount(), 0u) << describe(scene.log());
    EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << describe(scene.log());
    EXPECT_EQ(scene.stepCount(), kSteps);
    // Solvers sum up (and warn about) what went wrong over the run when the scene ends.
    scene.unload();
    EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << describe(scene.log());
    passed += stepped && scene.log().errorCount() == 0 &&
              scene.log().count(MessageLevel::warning) == 0;
  }
  std::printf(
      "[ bundled  ] %d of %zu scenes loaded and ran %d steps without a warning (%d skipped)\n",
      passed, scenes.size(), kSteps, skipped);
}

TEST(BundledScenes, FragmentsAreNotScenes) {
  for (const fs::path& file : bundledScenes())
    for (const auto& part : file) EXPECT_NE(part, "fragments") << file;
}

}  // namespace
}  // namespace stroma::test
