// SPDX-License-Identifier: MIT
// The step allocates nothing once warm (DESIGN.md section 5). Each bundled scene runs 20 steps
// to warm up (buffers sized, contacts found, sparsity patterns analyzed), then the heap
// allocations of the next 10 steps are counted: operator new, replaced for this program
// (tests/support/AllocationCounter.h). Eigen's dense temporaries go through malloc and are not
// counted. A scene must allocate nothing unless tests/scenes/step-allocations.txt gives it a
// ceiling (the scenes not yet allocation-free, with the reason): more than its ceiling fails,
// so an allocation added to a step is caught, and a scene that got better is told to lower it.
#include "support/AllocationCounter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWarmSteps = 20;
constexpr int kCountedSteps = 10;

// Scene (relative to scenes/) -> ceiling of allocations over the counted steps.
std::map<std::string, long> ceilings() {
  std::map<std::string, long> out;
  std::ifstream in(fs::path(STROMA_SOURCE_DIR) / "tests/scenes/step-allocations.txt");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string scene;
    long ceiling = 0;
    if (fields >> scene >> ceiling) out[scene] = ceiling;
  }
  return out;
}

std::vector<fs::path> bundledScenes(const fs::path& root) {
  std::vector<fs::path> scenes;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    if (it->is_directory() && it->path().filename() == "fragments") {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && it->path().extension() == ".scn") scenes.push_back(it->path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(StepAllocations, WarmStepsOfTheBundledScenesAllocateNothing) {
  const fs::path root = fs::path(STROMA_SOURCE_DIR) / "scenes";
  const std::map<std::string, long> allowed = ceilings();
  ASSERT_FALSE(allowed.empty()) << "tests/scenes/step-allocations.txt not found or empty";
  int free = 0, counted = 0;
  for (const fs::path& file : bundledScenes(root)) {
    const std::string name = fs::relative(file, root).generic_string();
    SCOPED_TRACE(name);
    Runtime runtime;
    Scene scene(runtime);
    if (!scene.loadFile(file)) {
      // Left out of this build (a library missing): BundledScenes_test says so.
      EXPECT_FALSE(findError(scene.log(), "which this build left out").text.empty())
          << describe(scene.log());
      continue;
    }
    for (int i = 0; i < kWarmSteps; ++i) ASSERT_TRUE(scene.step()) << describe(scene.log());
    g_allocations = 0;
    g_counting = true;
    bool stepped = true;
    for (int i = 0; i < kCountedSteps && stepped; ++i) stepped = scene.step();
    g_counting = false;
    ASSERT_TRUE(stepped) << describe(scene.log());
    const long n = g_allocations;
    const auto it = allowed.find(name);
    const long ceiling = it == allowed.end() ? 0 : it->second;
    ++counted;
    free += n == 0;
    std::printf("[ allocs   ] %6ld over %d warm steps (ceiling %ld)  %s\n", n, kCountedSteps,
                ceiling, name.c_str());
    EXPECT_LE(n, ceiling) << "a warm step allocates: " << n << " allocations over "
                          << kCountedSteps << " steps";
    if (it != allowed.end())
      EXPECT_LT(ceiling - n, std::max(10L, ceiling / 5))
          << "fewer allocations than its ceiling: lower it in tests/scenes/step-allocations.txt";
  }
  std::printf("[ allocs   ] %d of %d scenes allocate nothing in a warm step\n", free, counted);
  for (const auto& [scene, ceiling] : allowed)
    EXPECT_TRUE(fs::exists(root / scene)) << scene << " in step-allocations.txt is not a scene";
}

}  // namespace
}  // namespace stroma::test
