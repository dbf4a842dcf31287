// SPDX-License-Identifier: MIT
// libFuzzer target: arbitrary bytes as a URDF robot, opened as a scene by itself (Scene::loadFile
// wraps a .urdf file in a default scene holding a URDFLoader): urdfdom's parser, the loader's
// checks (masses, inertias, joint types), the generated subgraph (ArticulatedMapping,
// ArticulatedBodyMass, drives, limits, visual meshes) and two steps. Loading must report bad
// input through the scene's log, never crash, leak, hang or trip a sanitizer; a failed load must
// say why.
//
// Built by the sanitizer sub-build (tests/tooling/asan) and run by the ctest tooling_fuzz_urdf
// (tests/tooling/run_fuzzer.sh, from a scratch folder) with the seeds of fuzz/urdf_corpus:
//   URDFLoaderFuzzer WORK_CORPUS urdf_corpus/
// STROMA_PLUGIN_PATH must name the sub-build's plugins (built with the same sanitizers).
// LSAN_OPTIONS=suppressions=urdfdom.supp (set by the test) leaves out urdfdom's own leak of a
// robot whose joints make a cycle (see that file).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "core/Runtime.h"
#include "simulation/Scene.h"

namespace {

stroma::Runtime& runtime() {
  static stroma::Runtime instance;
  return instance;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (runtime().plugins().available().empty()) {
    std::fprintf(stderr,
                 "URDFLoaderFuzzer: no Stroma plugin found; set STROMA_PLUGIN_PATH to the "
                 "sanitizer build's lib/stroma/plugins\n");
    std::abort();
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The loader reads a file: the input becomes robot.urdf in the current (scratch) folder.
  {
    std::ofstream out("robot.urdf", std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  stroma::Scene scene(runtime());
  scene.setThreadCount(1);
  if (scene.loadFile("robot.urdf")) {
    scene.step();
    scene.step();
  } else if (scene.log().errorCount() == 0) {
    std::fprintf(stderr, "URDFLoaderFuzzer: a failed load without an error message\n");
    std::abort();
  }
  return 0;
}
