// SPDX-License-Identifier: MIT
#include "SceneViewer.h"

#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "core/Node.h"
#include "simulation/Scene.h"
#include "simulation/VisualModel.h"
#include "stroma/rendering/BitmapFont.h"
#include "stroma/rendering/PngImage.h"
#include "stroma/rendering/SceneBounds.h"
#include "stroma/rendering/SceneDrawer.h"

namespace stroma::viewer {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// Orbit: half a turn for a drag across the window's height.
constexpr double kOrbitRadiansPerHeight = kPi;
/// Zoom: each notch of the wheel comes 10 % closer (or goes 10 % farther).
constexpr double kZoomPerNotch = 0.9;
/// Points without triangles are grabbed within this many pixels of the mouse.
constexpr double kPointPickPixels = 6;

bool hasVisualModel(const Node& node) {
  if (node.get<VisualModel>()) return true;
  for (const auto& child : node.children())
    if (hasVisualModel(*child)) return true;
  return false;
}

/// What the scene asks to draw; a scene without visual models shows its FEM meshes and
/// points, so that it is not a blank window.
rendering::DrawOptions drawOptionsFor(const Node& root) {
  rendering::DrawOptions options;
  if (!hasVisualModel(root)) {
    std::string unknown;
    rendering::DisplayFlags flags = rendering::sceneDisplayFlags(root, unknown);
    flags.forceFields = true;
    flags.behaviorModels = true;
    options.flags = flags;
  }
  return options;
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

SceneViewer::SceneViewer(Scene& scene, ViewerSettings settings)
    : m_scene(scene), m_settings(settings) {
  m_running = m_settings.animate || m_scene.root().d_animate.value();
  m_drawer = std::make_unique<rendering::SceneDrawer>(m_scene.root());
  m_drawer->setOptions(drawOptionsFor(m_scene.root()));
  std::string warning;
  if (!m_camera.readSceneCamera(m_scene.root(), warning)) {
    fitCamera();
    m_cameraFitted = true;
  }
  if (!warning.empty()) std::cerr << "stroma view: camera: " << warning << '\n';
}

SceneViewer::~SceneViewer() {
  m_spring.release();
  if (m_drawer) m_drawer->releaseGLResources();
}

void SceneViewer::fitCamera() {
  m_drawer->updateVisuals();
  m_camera.fitBox(rendering::sceneBounds(m_scene.root()),
                  static_cast<double>(m_width) / static_cast<double>(m_height));
}

void SceneViewer::resize(int width, int height) {
  m_width = std::max(width, 1);
  m_height = std::max(height, 1);
  if (m_cameraFitted && m_drawer) fitCamera();
}

void SceneViewer::mouseButton(int button, int action, int mods) {
  if (action == GLFW_RELEASE) {
    if (m_drag == Drag::pull) m_spring.release();
    m_drag = Drag::none;
    return;
  }
  if (action != GLFW_PRESS || m_drag != Drag::none) return;
  if (button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_SHIFT)) {
    startPull(m_cursorX, m_cursorY);
  } else if (button == GLFW_MOUSE_BUTTON_LEFT) {
    m_drag = Drag::orbit;
  } else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) {
    m_drag = Drag::pan;
  }
}

void SceneViewer::startPull(double x, double y) {
  if (m_failed) return;
  const rendering::Ray ray = m_camera.unproject(x, y, m_width, m_height);
  // A cone of kPointPickPixels pixels: a pixel is 2 tan(fov / 2) / height per unit of
  // distance (perspective; the same at the lookAt distance for an orthographic view).
  const double pixel = 2 * std::tan(m_camera.fieldOfView * kPi / 360) / m_height;
  const auto picked = pickAlongRay(collectPickSurfaces(m_scene.root()), ray.origin,
                                   ray.direction, kPointPickPixels * pixel);
  if (!picked) return;
  m_pullDepth = (picked->hit - ray.origin).dot(m_camera.forward());
  if (m_spring.grab(*picked, pullTarget(x, y), m_settings.springStiffness)) m_drag = Drag::pull;
}

// The point under the mouse at the grabbed point's depth: on the plane facing the camera
// through it.
Vec3d SceneViewer::pullTarget(double x, double y) const {
  const rendering::Ray ray = m_camera.unproject(x, y, m_width, m_height);
  const double along = ray.direction.dot(m_camera.forward());
  return ray.origin + ray.direction * (m_pullDepth / std::max(along, 1e-9));
}

void SceneViewer::cursorMoved(double x, double y) {
  const double dx = x - m_cursorX, dy = y - m_cursorY;
  m_cursorX = x;
  m_cursorY = y;
  const double h = m_height;
  if (m_drag == Drag::orbit || m_drag == Drag::pan) m_cameraFitted = false;
  switch (m_drag) {
    case Drag::orbit:
      m_camera.orbit(-dx / h * kOrbitRadiansPerHeight, dy / h * kOrbitRadiansPerHeight);
      break;
    case Drag::pan:
      m_camera.pan(-dx / h, dy / h);
      break;
    case Drag::pull:
      m_spring.moveTarget(pullTarget(x, y));
      break;
    case Drag::none:
      break;
  }
}

void SceneViewer::scrolled(double yOffset) {
  m_camera.zoom(std::pow(kZoomPerNotch, yOffset));
  m_cameraFitted = false;
}

void SceneViewer::key(int key, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  switch (key) {
    case GLFW_KEY_SPACE:
      if (action != GLFW_PRESS) break;
      m_running = !m_running;
      // The rate counts from now: the time spent paused is no part of it.
      m_stepsInWindow = 0;
      m_windowStart = std::chrono::steady_clock::now();
      break;
    case GLFW_KEY_N:
    case GLFW_KEY_RIGHT:
      m_running = false;
      m_stepOnce = true;
      break;
    case GLFW_KEY_R:
      if (action == GLFW_PRESS) reset();
      break;
    case GLFW_KEY_S:
      if (action == GLFW_PRESS) m_screenshotRequested = true;
      break;
    case GLFW_KEY_H:
      if (action == GLFW_PRESS) m_settings.showText = !m_settings.showText;
      break;
    case GLFW_KEY_Q:
    case GLFW_KEY_ESCAPE:
      m_quit = true;
      break;
    default:
      break;
  }
}

bool SceneViewer::reset() {
  m_spring.release();
  m_drag = Drag::none;
  m_drawer.reset();
  const std::filesystem::path file = m_scene.file();
  m_failed = !m_scene.loadFile(file);
  if (m_failed) {
    std::cerr << "stroma view: " << file.string() << " no longer loads (errors above)\n";
    m_running = false;
    return false;
  }
  m_drawer = std::make_unique<rendering::SceneDrawer>(m_scene.root());
  m_drawer->setOptions(drawOptionsFor(m_scene.root()));
  m_lastStepMs = 0;
  return true;
}

bool SceneViewer::advance() {
  if (m_failed || (!m_running && !m_stepOnce)) return true;
  m_stepOnce = false;
  const auto start = std::chrono::steady_clock::now();
  const bool ok = m_scene.step();
  recordStep(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (!ok) {
    std::cerr << "stroma view: the step at time " << m_scene.root().time()
              << " s failed (errors above); paused\n";
    m_running = false;
  }
  return ok;
}

void SceneViewer::recordStep(double seconds) {
  m_lastStepMs = 1e3 * seconds;
  ++m_stepsInWindow;
  const auto now = std::chrono::steady_clock::now();
  const double window = std::chrono::duration<double>(now - m_windowStart).count();
  if (window >= 0.5) {
    m_stepsPerSecond = static_cast<double>(m_stepsInWindow) / window;
    m_stepsInWindow = 0;
    m_windowStart = now;
  }
}

// The spring as SOFA shows it: a line from the pulled point to the mouse, in the camera's
// matrices that SceneDrawer::draw leaves loaded.
void SceneViewer::drawSpring() const {
  const MouseSpringForceField* spring = m_spring.spring();
  if (!spring) return;
  const Vec3d from = m_spring.picked().state->readCoord(VecId::position())[spring->d_index.value()];
  const Vec3d& to = spring->d_target.value();
  glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT | GL_POINT_BIT | GL_CURRENT_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_DEPTH_TEST);  // seen through the body it pulls
  glLineWidth(2.0f);
  glColor3d(1.0, 0.85, 0.2);
  glBegin(GL_LINES);
  glVertex3d(from.x(), from.y(), from.z());
  glVertex3d(to.x(), to.y(), to.z());
  glEnd();
  glPointSize(7.0f);
  glBegin(GL_POINTS);
  glVertex3d(from.x(), from.y(), from.z());
  glVertex3d(to.x(), to.y(), to.z());
  glEnd();
  glPopAttrib();
}

void SceneViewer::saveScreenshot() {
  m_screenshotRequested = false;
  rendering::Image image;
  image.width = m_width;
  image.height = m_height;
  image.rgba.resize(static_cast<std::size_t>(4) * m_width * m_height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  rendering::flipRows(image);
  std::filesystem::path file;
  for (int n = 0; n < 10000; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "stroma-view-%04d.png", n);
    std::error_code ec;
    if (!std::filesystem::exists(name, ec)) {
      file = name;
      break;
    }
  }
  std::string error;
  if (file.empty())
    m_notice = "no screenshot: stroma-view-0000.png to -9999.png all exist";
  else if (rendering::writePng(file, image, error))
    m_notice = "saved " + std::filesystem::absolute(file).string();
  else
    m_notice = "no screenshot: " + error;
  std::cerr << "stroma view: " << m_notice << '\n';
}

std::vector<std::string> SceneViewer::statusLines() const {
  std::vector<std::string> lines;
  if (m_failed) return {"the scene failed to load: see the terminal; r to retry, q to quit"};
  std::string state = m_running ? "running" : "paused";
  state += "  t = " + format("%.4g", m_scene.root().time()) + " s";
  state += "  step " + format("%.2f", m_lastStepMs) + " ms";
  state += "  " + format("%.1f", m_running ? m_stepsPerSecond : 0.0) + " steps/s";
  lines.push_back(state);
  if (m_spring.active())
    lines.push_back("pulling point " + std::to_string(m_spring.picked().index) + " of " +
                    m_spring.picked().state->path() + "  k = " +
                    format("%g", m_spring.spring()->d_stiffness.value()) + " N/m");
  if (!m_notice.empty()) lines.push_back(m_notice);
  return lines;
}

void SceneViewer::drawFrame() {
  if (m_drawer) {
    m_camera.fitClipPlanes(rendering::sceneBounds(m_scene.root()));
    m_drawer->draw(m_camera, m_width, m_height);
    drawSpring();
    if (m_screenshotRequested) saveScreenshot();
  } else {  // the scene failed to load again: its graph is not there to draw
    glViewport(0, 0, m_width, m_height);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  if (!m_settings.showText) return;
  const int scale = m_width >= 800 ? 2 : 1;
  constexpr int kMargin = 8;
  const int lineHeight = rendering::textHeight(scale) + scale * 3;
  int y = kMargin;
  for (const std::string& line : statusLines()) {
    rendering::drawText(line, kMargin, y, scale, Vec4d(1, 1, 1, 1), m_width, m_height);
    y += lineHeight;
  }
  const std::string help =
      "space play/pause  n step  r reset  shift+drag pull  s screenshot  h text  q quit";
  rendering::drawText(help, kMargin, m_height - kMargin - rendering::textHeight(1), 1,
                      Vec4d(0.8, 0.8, 0.8, 1), m_width, m_height);
}

}  // namespace stroma::viewer
