// SPDX-License-Identifier: MIT
// `stroma render`: steps a scene as `stroma run` does and takes pictures of it offscreen
// (OSMesa), as numbered PNG files and/or a video through ffmpeg. The stroma program loads
// this module (dlopen) only for this command: batch runs never load OpenGL.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <future>
#include <iostream>
#include <memory>

#include "CommandLine.h"
#include "FrameSink.h"
#include "OffscreenContext.h"
#include "RenderOptions.h"
#include "core/Node.h"
#include "core/Runtime.h"
#include "simulation/Scene.h"
#include "stroma/rendering/Camera.h"
#include "stroma/rendering/SceneBounds.h"
#include "stroma/rendering/SceneDrawer.h"

namespace stroma::rendering {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Loads the scene with console (and JSON) messages, as `stroma run` does.
int loadScene(const cli::Arguments& a, Runtime& runtime, Scene& scene,
              std::unique_ptr<std::ofstream>& jsonFile) {
  for (const auto& dir : a.values("--data-path")) runtime.addDataDirectory(dir);
  scene.log().addSink(std::make_shared<StreamSink>(
      std::cerr, a.has("--verbose") ? MessageLevel::info : MessageLevel::warning));
  if (const std::string* json = a.value("--log-json")) {
    jsonFile = std::make_unique<std::ofstream>(*json);
    if (!*jsonFile) return cli::usageError("cannot write the JSON log '" + *json + "'");
    scene.log().addSink(std::make_shared<JsonLinesSink>(*jsonFile));
  }
  if (!scene.loadFile(a.positional.front())) {
    const std::size_t errors = scene.log().errorCount();
    std::cerr << "stroma: " << a.positional.front() << ": " << errors
              << (errors == 1 ? " error" : " errors") << "; the scene was not rendered\n";
    return cli::kBadInput;
  }
  return cli::kSuccess;
}

bool hasVisualStyle(const Node& root) {
  for (const auto& object : root.objects())
    if (object->className() == "VisualStyle") return true;
  return false;
}

/// Draws, reads back and sends one frame to the PNG folder and/or the video.
class FrameWriter {
 public:
  FrameWriter(const RenderOptions& options, OffscreenContext& context, SceneDrawer& drawer,
              Camera& camera, Scene& scene, VideoPipe* video)
      : m_o(options),
        m_context(context),
        m_drawer(drawer),
        m_camera(camera),
        m_scene(scene),
        m_video(video) {}

  /// Makes the camera, fitted to the scene at step 0, widen its view whenever a body leaves
  /// the box seen so far (a hanging or falling body stays in the picture; the view never
  /// narrows, so a film does not pump). `legendMargin`: the pixels a legend takes.
  void followBodies(const Aabb& seen, int legendMargin) {
    m_follow = true;
    m_seen = seen;
    m_legendMargin = legendMargin;
  }

  bool write(long long step) {
    const auto drawStart = Clock::now();
    const Aabb box = sceneBounds(m_scene.root());
    if (m_follow && !box.empty() && !(m_seen.contains(box.min) && m_seen.contains(box.max))) {
      m_seen.merge(box);
      m_camera.fitBox(m_seen, m_o.width, m_o.height, m_legendMargin);
    }
    m_camera.fitClipPlanes(box);
    m_drawer.draw(m_camera, m_o.width, m_o.height);
    m_context.readPixels(m_image);
    drawSeconds += secondsSince(drawStart);
    const FrameReport& report = m_drawer.lastFrame();
    if (report.drawn() == 0 && !m_warnedEmpty) {
      m_warnedEmpty = true;
      std::cerr << "stroma: warning: nothing was drawn in frame " << m_frame
                << ": the scene has no visual model with a surface, and its VisualStyle "
                   "(displayFlags) shows nothing else; the frame is written with the "
                   "background only (--show showBehavior draws the states)\n";
    }
    const auto saveStart = Clock::now();
    if (m_video && !m_video->write(m_image)) {
      std::cerr << "stroma: ffmpeg stopped reading frames (see its messages above)\n";
      return false;
    }
    std::string where;
    if (m_o.outputDirGiven || !m_video) {
      // The PNG file is compressed on another thread while the next steps run; one file at a
      // time, so that a failure stops the run at the next frame.
      if (!finish()) return false;
      const auto file = m_o.outputDir / frameFileName(m_frame);
      std::swap(m_image, m_writing);
      m_pending = std::async(std::launch::async, [file, this] {
        std::string error;
        return writePng(file, m_writing, error) ? std::string()
                                                : "cannot write " + file.string() + ": " + error;
      });
      where = " -> " + file.string();
    }
    saveSeconds += secondsSince(saveStart);
    std::printf("frame %05lld: step %lld, time %g s%s", m_frame, step, m_scene.root().time(),
                where.c_str());
    if (report.colorMapped)
      std::printf(", %s %s to %s %s", colorMapName(m_o.colorMap), report.legendMin.c_str(),
                  report.legendMax.c_str(), colorMapUnit(m_o.colorMap));
    std::printf("\n");
    ++m_frame;
    return true;
  }

  /// Waits for the PNG file being written. False (after saying why) when it failed.
  bool finish() {
    if (!m_pending.valid()) return true;
    const std::string error = m_pending.get();
    if (error.empty()) return true;
    std::cerr << "stroma: " << error << "\n";
    return false;
  }

  long long frames() const { return m_frame; }
  /// Time spent drawing and reading back; waiting for PNG files and sending video frames.
  double drawSeconds = 0, saveSeconds = 0;

 private:
  const RenderOptions& m_o;
  OffscreenContext& m_context;
  SceneDrawer& m_drawer;
  Camera& m_camera;
  Scene& m_scene;
  VideoPipe* m_video;
  Image m_image;
  Image m_writing;  ///< the frame whose PNG file m_pending writes
  std::future<std::string> m_pending;
  long long m_frame = 0;
  bool m_warnedEmpty = false;
  bool m_follow = false;
  Aabb m_seen;
  int m_legendMargin = 0;
};

int legendMargin(const RenderOptions& o) {
  const bool legend = o.colorMap != ColorMapKind::none && o.legend;
  return legend ? legendWidth(o.colorMap, o.width, o.height) : 0;
}

/// The view: --camera, else the scene's InteractiveCamera, else the whole scene at step 0 (in
/// the part of the picture a legend leaves), widened later as bodies move (`fitted`).
Camera chooseCamera(const RenderOptions& o, const Scene& scene, bool& fitted) {
  Camera camera;
  std::string warning;
  fitted = false;
  if (o.eyeAndTarget) {
    camera.setEyeAndTarget(o.eyeAndTarget->first, o.eyeAndTarget->second);
  } else if (!camera.readSceneCamera(scene.root(), warning)) {
    camera.fitBox(sceneBounds(scene.root()), o.width, o.height, legendMargin(o));
    fitted = true;
  }
  if (!warning.empty()) std::cerr << "stroma: warning: camera:" << warning << "\n";
  return camera;
}

/// A scene without VisualStyle and without a visual surface (most simulation scenes) would
/// give empty pictures: draw its FEM meshes, else its points, and say so.
void showSomething(SceneDrawer& drawer, const Camera& camera, const RenderOptions& o,
                   const DisplayFlags& sceneFlags) {
  drawer.draw(camera, o.width, o.height);
  if (drawer.lastFrame().drawn() > 0) return;
  DrawOptions options = drawer.options();
  DisplayFlags fallback = sceneFlags;
  fallback.forceFields = true;
  options.flags = fallback;
  drawer.setOptions(options);
  drawer.draw(camera, o.width, o.height);
  const char* shown = "showForceFields";
  if (drawer.lastFrame().drawn() == 0) {
    fallback.behaviorModels = true;
    options.flags = fallback;
    drawer.setOptions(options);
    shown = "showBehaviorModels";
  }
  std::cerr << "stroma: note: the scene has no visual surface and no VisualStyle: drawing "
            << "with displayFlags=\"" << shown << "\" (--show WORDS chooses)\n";
}

int renderCommand(const std::vector<std::string>& args) {
  cli::Arguments a;
  std::string error;
  if (!cli::parseArguments(args, renderValueOptions(), renderFlagOptions(), a, error))
    return cli::usageError(error);
  if (a.positional.size() != 1)
    return cli::usageError(a.positional.empty() ? "expected a scene file"
                                                : "expected one scene file, got " +
                                                      std::to_string(a.positional.size()));
  RenderOptions o;
  if (!parseRenderOptions(a, o, error)) return cli::usageError(error);

  // Everything that can be refused is refused before the scene is stepped.
  std::filesystem::path ffmpeg;
  if (!o.video.empty()) {
    ffmpeg = findOnPath("ffmpeg");
    if (ffmpeg.empty())
      return cli::usageError(
          "--video: ffmpeg not found: install Debian's ffmpeg (apt-get install "
          "ffmpeg), or leave out --video and make the video from the PNG frames");
  }
  if ((o.outputDirGiven || o.video.empty()) && !prepareOutputFolder(o.outputDir, error))
    return cli::usageError(error);

  Runtime runtime;
  Scene scene(runtime);
  scene.setThreadCount(static_cast<int>(o.threads));
  std::unique_ptr<std::ofstream> jsonFile;
  if (int code = loadScene(a, runtime, scene, jsonFile)) return code;
  const double dt = o.dt > 0 ? o.dt : scene.root().dt();

  OffscreenContext context;
  if (!context.create(o.width, o.height, error)) {
    std::cerr << "stroma: --size " << o.width << "x" << o.height << ": " << error << "\n";
    return cli::kBadInput;
  }
  SceneDrawer drawer(scene.root());
  DrawOptions drawOptions;
  drawOptions.colorMap = o.colorMap;
  drawOptions.legend = o.legend;
  drawer.setOptions(drawOptions);
  if (o.colorMap != ColorMapKind::none) {
    std::vector<PointField> fields;
    if (!computePointFields(scene.root(), o.colorMap, fields, error))
      return cli::usageError("--color-map " + std::string(colorMapName(o.colorMap)) + ": " + error);
  }

  std::string unknown;
  DisplayFlags sceneFlags = sceneDisplayFlags(scene.root(), unknown);
  if (!o.show.empty()) {
    unknown.clear();
    sceneFlags.apply(o.show, unknown);
    if (!unknown.empty()) return cli::usageError("--show: unknown display flags: " + unknown);
    drawOptions.flags = sceneFlags;
    drawer.setOptions(drawOptions);
  }

  drawer.updateVisuals();
  bool fittedCamera = false;
  Camera camera = chooseCamera(o, scene, fittedCamera);
  if (!drawOptions.flags && !hasVisualStyle(scene.root()))
    showSomething(drawer, camera, o, sceneFlags);

  std::unique_ptr<VideoPipe> video;
  if (!o.video.empty()) {
    video = std::make_unique<VideoPipe>();
    if (!video->open(ffmpeg, o.video, o.width, o.height, error)) {
      std::cerr << "stroma: --video: " << error << "\n";
      return cli::kSimulationFailure;
    }
  }

  const long long every = o.every > 0 ? o.every : std::max<long long>(o.steps, 1);
  FrameWriter frames(o, context, drawer, camera, scene, video.get());
  if (fittedCamera) frames.followBodies(sceneBounds(scene.root()), legendMargin(o));
  int code = cli::kSuccess;
  const auto start = Clock::now();
  double stepSeconds = 0;
  if (!frames.write(0)) code = cli::kSimulationFailure;
  for (long long step = 1; code == cli::kSuccess && step <= o.steps; ++step) {
    const auto stepStart = Clock::now();
    const bool stepped = scene.step(dt);
    stepSeconds += secondsSince(stepStart);
    if (!stepped) {
      std::cerr << "stroma: the simulation failed at step " << step << " (time "
                << scene.root().time() << " s); see the errors above\n";
      code = cli::kSimulationFailure;
      // The picture of the failed state helps to see what went wrong.
      frames.write(step);
      break;
    }
    if ((step % every == 0 || step == o.steps) && !frames.write(step))
      code = cli::kSimulationFailure;
  }
  const auto lastFileStart = Clock::now();
  if (!frames.finish()) code = cli::kSimulationFailure;
  frames.saveSeconds += secondsSince(lastFileStart);
  if (code == cli::kSuccess && scene.log().runFailureCount() > 0) {
    // onDivergence="warn" let a diverged state go on: the run is still not a success.
    std::cerr << "stroma: the run went on after its state diverged (onDivergence=\"warn\"); "
                 "see the warnings above\n";
    code = cli::kSimulationFailure;
  }
  if (video && !video->close(error)) {
    std::cerr << "stroma: --video " << o.video << ": " << error << "\n";
    code = cli::kSimulationFailure;
  }
  drawer.releaseGLResources();
  const double total = secondsSince(start);
  std::printf(
      "Rendered %lld frames of %dx%d with %s in %.3f s (%.1f frames/s): drawing %.3f s "
      "(%.1f frames/s), waiting for files %.3f s, stepping %.3f s\n",
      frames.frames(), o.width, o.height, context.renderer().c_str(), total,
      total > 0 ? static_cast<double>(frames.frames()) / total : 0.0, frames.drawSeconds,
      frames.drawSeconds > 0 ? static_cast<double>(frames.frames()) / frames.drawSeconds : 0.0,
      frames.saveSeconds, stepSeconds);
  if (video && code == cli::kSuccess) std::printf("Video: %s\n", o.video.c_str());
  return code;
}

}  // namespace

}  // namespace stroma::rendering

/// The entry point `stroma render` resolves with dlsym: the arguments after "render".
extern "C" __attribute__((visibility("default"))) int stroma_render_main(int argc,
                                                                         const char* const* argv) {
  try {
    return stroma::rendering::renderCommand(std::vector<std::string>(argv, argv + argc));
  } catch (const std::exception& e) {
    std::cerr << "stroma: internal error: " << e.what() << '\n';
    return stroma::cli::kSimulationFailure;
  }
}
