// SPDX-License-Identifier: MIT
#include "simulation/Scene.h"

#include <fstream>
#include <sstream>

#include "core/Runtime.h"
#include "simulation/AnimationLoop.h"
#include "simulation/ModelSceneWrapper.h"
#include "simulation/SceneLoader.h"
#include "simulation/SceneXml.h"
#include "simulation/StepListener.h"
#include "simulation/Visitor.h"

namespace stroma {

namespace fs = std::filesystem;

Scene::Scene(Runtime& runtime) : m_runtime(runtime), m_pool(std::make_unique<ThreadPool>(0)) {}

void Scene::setThreadCount(int threads) {
  m_pool = std::make_unique<ThreadPool>(threads);
  if (m_root) m_root->setThreadPool(m_pool.get());
}

Scene::~Scene() { unload(); }

namespace {
class CleanupVisitor final : public Visitor {
 public:
  void processNodeBottomUp(Node& node) override {
    for (const auto& o : node.objects()) o->cleanup();
  }
  std::string_view name() const override { return "cleanup"; }
};
}  // namespace

void Scene::unload() {
  if (m_root && m_loaded) {
    CleanupVisitor cleanup;
    traverse(*m_root, cleanup);
  }
  m_stepListeners.clear();
  m_root.reset();
  m_loaded = false;
  m_steps = 0;
}

bool Scene::loadFile(const fs::path& file) {
  std::error_code ec;
  std::ifstream in;
  if (fs::is_regular_file(file, ec)) in.open(file, std::ios::binary);
  if (!in.is_open()) {
    Message m;
    m.level = MessageLevel::error;
    m.text = "cannot open scene file '" + file.string() + "'";
    m.where.file = file.string();
    m_log.add(std::move(m));
    return false;
  }
  // A model file (a robot's URDF) is a scene by itself: it is loaded in a default scene.
  if (const std::string wrapped = wrapModelInScene(file); !wrapped.empty())
    return load(wrapped, file);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return load(buffer.str(), file);
}

bool Scene::loadString(std::string_view xml, const fs::path& fileName) {
  return load(xml, fileName);
}

bool Scene::load(std::string_view xml, const fs::path& file) {
  unload();
  m_file = file;
  ScopedPhase phase(m_timing, "load+init");
  const std::size_t errorsBefore = m_log.errorCount();
  SceneElement root;
  auto resolveInclude = [this](const std::string& href, const fs::path& from) {
    return m_runtime.findFile(href, {from, m_file.parent_path()});
  };
  if (!parseSceneXml(xml, file, resolveInclude, m_log, root)) return false;
  const bool built = buildSceneGraph(m_runtime, root, file, m_log, m_root, m_pool.get());
  if (m_root) m_root->setMessageLog(&m_log);
  m_loaded = built && m_log.errorCount() == errorsBefore;
  if (m_loaded) collectStepListeners(*m_root, m_stepListeners);
  return m_loaded;
}

bool Scene::step(double dt) {
  if (!m_loaded) return false;
  if (dt <= 0) dt = m_root->dt();
  const std::size_t errorsBefore = m_log.errorCount();
  {
    ScopedPhase phase(m_timing, "step");
    for (StepListener* listener : m_stepListeners) listener->stepBegin(m_root->time(), dt);
    if (AnimationLoop* loop = m_root->get<AnimationLoop>()) loop->step(*m_root, dt, m_timing);
    else animateDefault(*m_root, dt, m_timing);
  }
  // Outside the step's timing: what listeners write (exports) is not simulation time.
  if (!m_stepListeners.empty()) {
    ScopedPhase phase(m_timing, "stepListeners");
    for (StepListener* listener : m_stepListeners) listener->stepEnd(m_root->time(), dt);
  }
  ++m_steps;
  return m_log.errorCount() == errorsBefore;
}

}  // namespace stroma
