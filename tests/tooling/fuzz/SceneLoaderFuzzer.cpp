// SPDX-License-Identifier: MIT
// libFuzzer target: arbitrary bytes as a scene. Loading must report bad input through the
// scene's log, never crash, leak, hang or trip a sanitizer; a scene that loads is stepped once.
//
// Built by the sanitizer sub-build (tests/tooling/asan) and run by the ctest tooling_fuzz
// (tests/tooling/run_fuzzer.sh) with the seed corpus and dictionary of this folder:
//   SceneLoaderFuzzer -dict=scene.dict WORK_CORPUS corpus/
// STROMA_PLUGIN_PATH must name the sub-build's plugins (built with the same sanitizers).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "core/Runtime.h"
#include "simulation/Scene.h"

namespace {

/// One Runtime for the whole run, as an application keeps one: its plugins stay loaded across
/// inputs, so that an input's state leaking into the next one shows up too.
stroma::Runtime& runtime() {
  static stroma::Runtime instance;
  return instance;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Without plugins every component is unknown and the fuzzer would only exercise the parser.
  if (runtime().plugins().available().empty()) {
    std::fprintf(stderr,
                 "SceneLoaderFuzzer: no Stroma plugin found; set STROMA_PLUGIN_PATH to the "
                 "sanitizer build's lib/stroma/plugins\n");
    std::abort();
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view xml(reinterpret_cast<const char*>(data), size);
  stroma::Scene scene(runtime());
  scene.setThreadCount(1);
  if (scene.loadString(xml, "fuzz.scn")) scene.step();
  return 0;
}
