// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/Message.h"
#include "core/Node.h"
#include "core/ThreadPool.h"
#include "simulation/Timing.h"

namespace stroma {

class Runtime;
class StepListener;

/// One simulated scene: its graph, its messages and its timings. Scenes are independent of
/// each other; several may live in one process and be stepped from different threads.
///
///   Runtime runtime;
///   Scene scene(runtime);
///   scene.log().addSink(...);
///   if (!scene.loadFile("liver.scn")) return 2;   // every problem is in scene.log()
///   for (int i = 0; i < 100; ++i) if (!scene.step()) return 1;
class Scene {
 public:
  explicit Scene(Runtime& runtime);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  /// Reads, builds, links and initializes a scene (.scn or .xml). Returns false when anything
  /// was wrong; each problem is then an error in log(), with file, line, component and field.
  bool loadFile(const std::filesystem::path& file);
  /// The same from text; `fileName` is used in messages and to resolve relative paths.
  bool loadString(std::string_view xml, const std::filesystem::path& fileName = "<string>");

  /// Advances by one step of `dt` (the root's dt when dt <= 0): the StepListeners' stepBegin,
  /// the animation loop's step, then their stepEnd. Returns false when the step reported an
  /// error (a diverging simulation, a listener that failed), which the log details.
  bool step(double dt = 0);

  Node& root() { return *m_root; }
  const Node& root() const { return *m_root; }
  bool isLoaded() const { return m_loaded; }
  MessageLog& log() { return m_log; }
  Timing& timing() { return m_timing; }
  Runtime& runtime() { return m_runtime; }
  const std::filesystem::path& file() const { return m_file; }
  long long stepCount() const { return m_steps; }

  /// Threads that parallel element loops of this scene may use (0: all cores). Set before
  /// loading, or between steps.
  void setThreadCount(int threads);
  int threadCount() const { return m_pool->threadCount(); }

  /// Cleans up and destroys the graph; the scene can then load again.
  void unload();

 private:
  bool load(std::string_view xml, const std::filesystem::path& file);

  Runtime& m_runtime;
  MessageLog m_log;
  Timing m_timing;
  std::unique_ptr<Node> m_root;
  std::filesystem::path m_file;
  long long m_steps = 0;
  std::vector<StepListener*> m_stepListeners;  ///< found once, after loading
  std::unique_ptr<ThreadPool> m_pool;
  bool m_loaded = false;
};

}  // namespace stroma
