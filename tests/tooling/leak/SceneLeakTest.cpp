// SPDX-License-Identifier: MIT
// Leak test, run under AddressSanitizer's LeakSanitizer by the ctest tooling_leak:
//   1. one Runtime loads, steps and unloads a scene 100 times (fresh Scene objects, and one
//      Scene reused), and the heap in use must not grow from one load to the next;
//   2. ten Runtimes are created, load the scene (loading its plugins) and are destroyed, which
//      unloads the plugins.
// Unreachable memory is reported by LeakSanitizer at exit (non-zero exit code); memory still
// reachable but growing per load (a cache or registry that is never trimmed) by the check of
// step 1. Usage: SceneLeakTest SCENE
#include <sanitizer/allocator_interface.h>

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/Runtime.h"
#include "simulation/Scene.h"

namespace {

constexpr int kLoads = 100;
constexpr int kRuntimes = 10;
/// Heap growth allowed between the 10th and the last load (allocator and libstdc++ noise).
constexpr std::size_t kGrowthAllowance = 64 * 1024;

bool loadStepUnload(stroma::Scene& scene, const std::filesystem::path& file) {
  if (!scene.loadFile(file)) {
    std::cerr << "SceneLeakTest: " << file << " failed to load\n";
    for (const auto& m : scene.log().messages()) std::cerr << stroma::formatForConsole(m) << '\n';
    return false;
  }
  if (!scene.step()) {
    std::cerr << "SceneLeakTest: " << file << " failed to step\n";
    return false;
  }
  scene.unload();
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: SceneLeakTest SCENE\n";
    return 2;
  }
  const std::filesystem::path file = argv[1];

  // 1. One Runtime, many loads.
  {
    stroma::Runtime runtime;
    std::size_t heapAfterWarmUp = 0;
    for (int i = 0; i < kLoads; ++i) {
      stroma::Scene scene(runtime);
      scene.setThreadCount(1);
      if (!loadStepUnload(scene, file)) return 1;
      if (i == 9) heapAfterWarmUp = __sanitizer_get_current_allocated_bytes();
    }
    const std::size_t heapAtEnd = __sanitizer_get_current_allocated_bytes();
    std::cout << "SceneLeakTest: " << kLoads
              << " loads with one Runtime; heap in use after load 10: " << heapAfterWarmUp
              << " B, after load " << kLoads << ": " << heapAtEnd << " B\n";
    if (heapAtEnd > heapAfterWarmUp + kGrowthAllowance) {
      std::cerr << "SceneLeakTest: the heap grew by " << heapAtEnd - heapAfterWarmUp << " B over "
                << kLoads - 10 << " loads: something keeps memory per load\n";
      return 1;
    }

    // The same Scene object loading again and again (load() unloads the previous graph).
    stroma::Scene reused(runtime);
    reused.setThreadCount(1);
    for (int i = 0; i < kLoads; ++i)
      if (!reused.loadFile(file) || !reused.step()) {
        std::cerr << "SceneLeakTest: reloading " << file << " failed at load " << i + 1 << '\n';
        return 1;
      }
  }

  // 2. Runtimes created and destroyed, each loading (then unloading) the plugins.
  for (int i = 0; i < kRuntimes; ++i) {
    stroma::Runtime runtime;
    stroma::Scene scene(runtime);
    scene.setThreadCount(1);
    if (!loadStepUnload(scene, file)) return 1;
    if (runtime.plugins().loadedPlugins().empty()) {
      std::cerr << "SceneLeakTest: the scene loaded no plugin; the test would prove nothing\n";
      return 1;
    }
  }
  std::cout << "SceneLeakTest: " << kRuntimes << " Runtimes created and destroyed\n";
  return 0;  // LeakSanitizer checks at exit
}
