// SPDX-License-Identifier: MIT
// What `stroma view` does with a scene, apart from the window: the camera moved by the mouse,
// play, pause, step and reset from the keys, the mouse spring, the step timings, and the frame
// drawn with the Rendering plugin's SceneDrawer. Input arrives as GLFW's codes and window
// pixels (x right, y down), from the window's callbacks or from a test.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "MouseSpringInteraction.h"
#include "stroma/rendering/Camera.h"

namespace stroma {
class Scene;
}
namespace stroma::rendering {
class SceneDrawer;
}

namespace stroma::viewer {

struct ViewerSettings {
  /// The mouse spring's stiffness (N/m); <= 0: kSpringStiffnessPerKilogram times the
  /// grabbed body's mass.
  double springStiffness = 0;
  /// Start running rather than paused (the scene's root `animate` also starts it).
  bool animate = false;
  /// Draw the heads-up text (the 'h' key toggles it).
  bool showText = true;
};

class SceneViewer {
 public:
  /// `scene` is loaded from `file`; reset() loads it again from there.
  SceneViewer(Scene& scene, ViewerSettings settings);
  ~SceneViewer();
  SceneViewer(const SceneViewer&) = delete;
  SceneViewer& operator=(const SceneViewer&) = delete;

  // --- Input (GLFW's codes; pixel coordinates of the window, y down) ---
  void mouseButton(int button, int action, int mods);
  void cursorMoved(double x, double y);
  void scrolled(double yOffset);
  void key(int key, int action, int mods);
  /// The size of the picture in pixels (the framebuffer's).
  void resize(int width, int height);

  // --- The loop ---
  /// Steps the scene when running or when a single step was asked for. Returns false when the
  /// step failed (the viewer then pauses; the scene's log says why).
  bool advance();
  /// Draws the scene and the heads-up text into the current OpenGL context.
  void drawFrame();
  bool quitRequested() const { return m_quit; }
  bool running() const { return m_running; }

  /// Loads the scene again from its file (the 'r' key), camera kept. Returns false when the
  /// file no longer loads (the log says why; the viewer then shows nothing and cannot step).
  bool reset();

  rendering::Camera& camera() { return m_camera; }
  int width() const { return m_width; }
  int height() const { return m_height; }
  const MouseSpringInteraction& mouseSpring() const { return m_spring; }
  /// The heads-up lines of the next frame (state, timings, what is grabbed).
  std::vector<std::string> statusLines() const;

 private:
  enum class Drag { none, orbit, pan, pull };
  void startPull(double x, double y);
  Vec3d pullTarget(double x, double y) const;
  void fitCamera();
  void drawSpring() const;
  /// Writes the picture just drawn (without the text) as the next free
  /// stroma-view-NNNN.png of the working folder.
  void saveScreenshot();
  void recordStep(double seconds);

  Scene& m_scene;
  ViewerSettings m_settings;
  std::unique_ptr<rendering::SceneDrawer> m_drawer;
  rendering::Camera m_camera;
  MouseSpringInteraction m_spring;
  int m_width = 800, m_height = 600;
  bool m_running = false, m_stepOnce = false, m_quit = false, m_failed = false;
  bool m_screenshotRequested = false;
  std::string m_notice;  ///< a line for the text: the last screenshot written, or why not
  Drag m_drag = Drag::none;
  /// Whether the camera still frames the whole scene as fitCamera() left it (not the scene's
  /// camera, not moved by the user): a resize then fits it again to the new shape.
  bool m_cameraFitted = false;
  double m_cursorX = 0, m_cursorY = 0;
  double m_pullDepth = 0;  ///< view depth of the grabbed point (along the camera's forward)
  // Timings: the last step's wall time, and steps per second over the last half second.
  double m_lastStepMs = 0, m_stepsPerSecond = 0;
  long long m_stepsInWindow = 0;
  std::chrono::steady_clock::time_point m_windowStart = std::chrono::steady_clock::now();
};

}  // namespace stroma::viewer
