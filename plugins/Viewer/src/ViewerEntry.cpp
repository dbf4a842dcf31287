// SPDX-License-Identifier: MIT
// The module's entry point, which `stroma view` calls after opening the module with dlopen
// (applications/stroma/ModuleCommand.cpp): parse the options, open the window, load the scene,
// and loop on step, draw, input until the window closes or the user quits.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "CommandLine.h"
#include "SceneViewer.h"
#include "ViewerWindow.h"
#include "core/Message.h"
#include "core/Runtime.h"
#include "simulation/Scene.h"

namespace stroma::viewer {

namespace {

using cli::kBadInput;
using cli::kSuccess;

/// While running, steps follow each other for about this long before the next frame is drawn
/// (a frame at 60 Hz leaves a few ms to draw): a fast scene runs at its own rate, not at one
/// step per frame.
constexpr double kStepBudgetSeconds = 0.012;

struct ViewOptions {
  std::string scene;
  std::vector<std::string> dataPaths;
  int width = 1280, height = 720;
  long long threads = 0, frames = 0;
  bool verbose = false;
  ViewerSettings settings;
};

/// "WxH" with both in 1..16384.
bool readSize(const std::string& text, int& width, int& height, std::string& error) {
  std::istringstream in(text);
  char x = 0;
  long long w = 0, h = 0;
  if (!(in >> w >> x >> h) || x != 'x' || !in.eof() || w < 1 || h < 1 || w > 16384 ||
      h > 16384) {
    error = "--size " + text + ": expected WIDTHxHEIGHT in pixels, each 1 to 16384 (as 1280x720)";
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

/// Reads the command line (Usage.cpp documents it). Returns false with `error` on bad input.
bool parseViewOptions(const std::vector<std::string>& args, ViewOptions& o, std::string& error) {
  cli::Arguments a;
  if (!cli::parseArguments(args, {"--size", "--threads", "--spring-stiffness", "--frames",
                                  "--data-path"},
                           {"--animate", "--verbose"}, a, error))
    return false;
  if (a.positional.size() != 1) {
    error = a.positional.empty() ? "expected a scene file"
                                 : "expected one scene file, got " +
                                       std::to_string(a.positional.size());
    return false;
  }
  o.scene = a.positional.front();
  o.dataPaths = a.values("--data-path");
  o.verbose = a.has("--verbose");
  o.settings.animate = a.has("--animate");
  if (const std::string* size = a.value("--size");
      size && !readSize(*size, o.width, o.height, error))
    return false;
  if (!cli::readInteger(a, "--threads", 0, o.threads, error) ||
      !cli::readInteger(a, "--frames", 1, o.frames, error) ||
      !cli::readReal(a, "--spring-stiffness", o.settings.springStiffness, error))
    return false;
  if (a.value("--spring-stiffness") && o.settings.springStiffness <= 0) {
    error = "--spring-stiffness must be positive (N/m)";
    return false;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(o.scene, ec)) {
    error = "cannot open scene file '" + o.scene + "'";
    return false;
  }
  return true;
}

int runViewer(const ViewOptions& o) {
  // The window first: without a display there is nothing to load the scene for.
  ViewerWindow window(o.width, o.height, "Stroma - " + o.scene);
  if (!window.isOpen()) {
    std::cerr << "stroma view: " << window.error() << '\n';
    return kBadInput;
  }
  Runtime runtime;
  for (const std::string& dir : o.dataPaths) runtime.addDataDirectory(dir);
  Scene scene(runtime);
  scene.setThreadCount(static_cast<int>(o.threads));
  scene.log().addSink(std::make_shared<StreamSink>(
      std::cerr, o.verbose ? MessageLevel::info : MessageLevel::warning));
  if (!scene.loadFile(o.scene)) {
    const std::size_t errors = scene.log().errorCount();
    std::cerr << "stroma view: " << o.scene << ": " << errors
              << (errors == 1 ? " error" : " errors") << "; the scene was not shown\n";
    return kBadInput;
  }

  SceneViewer viewer(scene, o.settings);
  window.attach(&viewer);
  for (long long frame = 0; !window.closeRequested() && !viewer.quitRequested() &&
                            (o.frames <= 0 || frame < o.frames);
       ++frame) {
    const auto frameStart = std::chrono::steady_clock::now();
    do {
      viewer.advance();
    } while (viewer.running() &&
             std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart)
                     .count() < kStepBudgetSeconds);
    viewer.drawFrame();
    window.present(viewer.running());
  }
  window.attach(nullptr);
  return kSuccess;
}

}  // namespace

}  // namespace stroma::viewer

/// `stroma view ARGS...` (the arguments after "view"). Returns the command's exit code.
extern "C" __attribute__((visibility("default"))) int stroma_viewer_main(int argc,
                                                                         const char* const* argv) {
  using namespace stroma;
  try {
    viewer::ViewOptions options;
    std::string error;
    if (!viewer::parseViewOptions(std::vector<std::string>(argv, argv + argc), options, error))
      return cli::usageError(error);
    return viewer::runViewer(options);
  } catch (const std::exception& e) {
    std::cerr << "stroma view: internal error: " << e.what() << '\n';
    return cli::kSimulationFailure;
  }
}
