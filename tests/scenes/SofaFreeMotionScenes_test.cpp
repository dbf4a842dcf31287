// SPDX-License-Identifier: MIT
// The SOFA scenes of ../shared/sofa with a FreeMotionAnimationLoop that Stroma runs (listed in
// sofa-freemotion-scenes.txt, beside this file, with what the others lack) load and run 100
// steps unmodified, without an error, with finite states that stay within 100 times their
// initial extent (a constraint problem that blows up leaves it within a few steps). Among them
// Demos/fallingBeamLagrangianCollision.scn. Skipped, with a message, without ../shared or
// without the Collision plugin (a build without Bullet).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "scenes/SceneLists.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSofaDir = fs::path(STROMA_SHARED_DIR) / "sofa";

std::vector<std::string> freeMotionScenes() {
  return readSceneList(fs::path(STROMA_SOURCE_DIR) / "tests/scenes/sofa-freemotion-scenes.txt");
}

// The largest |component| of the positions (or velocities) of every state; infinity when one
// is not finite.
double largest(const Node& node, VecId v) {
  double m = 0;
  for (const auto& o : node.objects())
    if (const auto* state = dynamic_cast<const BaseMechanicalState*>(o.get())) {
      std::size_t where = 0;
      const double s = state->vMaxAbs(v, where);
      m = std::isfinite(s) ? std::max(m, s) : HUGE_VAL;
    }
  for (const auto& c : node.children()) m = std::max(m, largest(*c, v));
  return m;
}

TEST(SofaFreeMotionScenes, EachRuns100StepsWithoutErrorAndStaysBounded) {
  if (!fs::is_directory(kSofaDir / "examples"))
    GTEST_SKIP() << "SOFA's scenes are not at " << kSofaDir
                 << " (the shared test data lives beside the clone)";
  Runtime runtime;
  if (const std::string why = pluginLeftOut(runtime, "Collision"); !why.empty())
    GTEST_SKIP() << "this build left the Collision plugin out: " << why;
  runtime.addDataDirectory(kSofaDir / "share");
  runtime.addDataDirectory(kSofaDir / "examples");
  const std::vector<std::string> scenes = freeMotionScenes();
  ASSERT_GE(scenes.size(), 8u);
  EXPECT_NE(std::find(scenes.begin(), scenes.end(),
                      "examples/Demos/fallingBeamLagrangianCollision.scn"),
            scenes.end());
  int passed = 0;
  for (const std::string& name : scenes) {
    SCOPED_TRACE(name);
    Scene scene(runtime);
    scene.setThreadCount(1);
    if (!scene.loadFile(kSofaDir / name)) {
      ADD_FAILURE() << "does not load:\n" << describe(scene.log());
      continue;
    }
    const double extent = largest(scene.root(), VecId::position());
    bool stepped = true;
    for (int i = 0; i < 100 && stepped; ++i) stepped = scene.step();
    EXPECT_TRUE(stepped) << describe(scene.log());
    EXPECT_EQ(scene.log().runFailureCount(), 0u) << describe(scene.log());
    const double reach = largest(scene.root(), VecId::position());
    const bool finite = std::isfinite(reach) && std::isfinite(largest(scene.root(), VecId::velocity()));
    EXPECT_TRUE(finite);
    const bool bounded = reach <= 100 * (1 + extent);
    EXPECT_TRUE(bounded) << "positions reach " << reach << " from an extent of " << extent;
    passed += stepped && finite && bounded && scene.log().runFailureCount() == 0;
  }
  std::printf("[ freemotion] %d of %zu SOFA scenes with a FreeMotionAnimationLoop ran 100 steps\n",
              passed, scenes.size());
}

}  // namespace
}  // namespace stroma::test
