// SPDX-License-Identifier: MIT
// stroma-bench-rendering: the parts of a frame of `stroma render` (plugins/Rendering) on the
// default organ scene (scenes/organ/Organ.scn: 935 points, 3579 tetrahedra, its FEM surface
// drawn), in an OSMesa context. bench/README.md and plugins/Rendering/README.md have the numbers.
//
// Draw/<width>/<height>/<colorMap>: SceneDrawer::draw and glFinish plus reading the pixels back,
//   the state after 20 steps (no stepping in the loop); colorMap 1 adds the displacement field,
//   its colors and the legend.
// WritePng/<width>/<height>: one frame to a PNG file (libpng, fast setting).
// Frame/<width>/<height>: what `stroma render --every 1` does per step: a step, the drawing, the
//   read-back and the PNG file.
// Wall-clock time (UseRealTime): llvmpipe rasterizes on threads of its own, which the main
// thread's CPU time leaves out.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

#include "OffscreenContext.h"
#include "core/Runtime.h"
#include "simulation/Scene.h"
#include "stroma/rendering/Camera.h"
#include "stroma/rendering/SceneBounds.h"
#include "stroma/rendering/SceneDrawer.h"

namespace stroma::bench {
namespace {

using namespace stroma::rendering;

/// The organ scene after `steps` steps, a drawer and a fitted camera, in a context of the size.
struct OrganPicture {
  OffscreenContext context;
  Runtime runtime;
  Scene scene{runtime};
  std::unique_ptr<SceneDrawer> drawer;
  Camera camera;
  Image image;
  int width, height;

  OrganPicture(int w, int h, ColorMapKind colorMap, int steps) : width(w), height(h) {
    std::string error;
    if (!context.create(w, h, error)) throw std::runtime_error(error);
    if (!scene.loadFile(std::filesystem::path(STROMA_SOURCE_DIR) / "scenes/organ/Organ.scn"))
      throw std::runtime_error("scenes/organ/Organ.scn does not load");
    drawer = std::make_unique<SceneDrawer>(scene.root());
    DrawOptions options;
    DisplayFlags flags;
    flags.forceFields = true;  // what stroma render draws for a scene without visual models
    options.flags = flags;
    options.colorMap = colorMap;
    drawer->setOptions(options);
    drawer->updateVisuals();
    camera.fitBox(sceneBounds(scene.root()), double(w) / h);
    for (int i = 0; i < steps; ++i) scene.step();
  }
  void drawAndRead() {
    camera.fitClipPlanes(sceneBounds(scene.root()));
    drawer->draw(camera, width, height);
    context.readPixels(image);
  }
};

void Draw(benchmark::State& state) {
  OrganPicture picture(int(state.range(0)), int(state.range(1)),
                       state.range(2) ? ColorMapKind::displacement : ColorMapKind::none, 20);
  for (auto _ : state) {
    picture.drawAndRead();
    benchmark::DoNotOptimize(picture.image.rgba.data());
  }
  state.counters["triangles"] = double(picture.drawer->lastFrame().triangles);
  state.counters["frames/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(Draw)
    ->Args({1280, 720, 0})
    ->Args({1280, 720, 1})
    ->Args({640, 480, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void WritePng(benchmark::State& state) {
  OrganPicture picture(int(state.range(0)), int(state.range(1)), ColorMapKind::none, 20);
  picture.drawAndRead();
  const auto file = std::filesystem::temp_directory_path() / "stroma-bench-rendering.png";
  std::string error;
  for (auto _ : state)
    if (!writePng(file, picture.image, error)) state.SkipWithError(error.c_str());
  std::filesystem::remove(file);
  state.counters["frames/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(WritePng)->Args({1280, 720})->Unit(benchmark::kMillisecond)->UseRealTime();

void Frame(benchmark::State& state) {
  OrganPicture picture(int(state.range(0)), int(state.range(1)), ColorMapKind::none, 0);
  const auto file = std::filesystem::temp_directory_path() / "stroma-bench-rendering-frame.png";
  std::string error;
  for (auto _ : state) {
    picture.scene.step();
    picture.drawAndRead();
    if (!writePng(file, picture.image, error)) state.SkipWithError(error.c_str());
  }
  std::filesystem::remove(file);
  state.counters["frames/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(Frame)->Args({1280, 720})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace stroma::bench

BENCHMARK_MAIN();
