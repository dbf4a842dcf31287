// SPDX-License-Identifier: MIT
// The viewer's GLFW window: a legacy (compatibility) OpenGL context through GLX, its input
// callbacks handed to a SceneViewer.
#pragma once

#include <string>

struct GLFWwindow;

namespace stroma::viewer {

class SceneViewer;

class ViewerWindow {
 public:
  /// Initializes GLFW and opens a window with its context current. Check isOpen(); when it
  /// is not, error() says why (no display, GLFW's own message).
  ViewerWindow(int width, int height, const std::string& title);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  bool isOpen() const { return m_window != nullptr; }
  const std::string& error() const { return m_error; }
  GLFWwindow* handle() const { return m_window; }

  /// Sends the window's input to `viewer` (nullptr: to nobody) and tells it the framebuffer
  /// size.
  void attach(SceneViewer* viewer);
  /// Shows what was drawn, then handles the pending input: without waiting while `busy` (a
  /// running simulation), else sleeping until input comes or `idleSeconds` pass.
  void present(bool busy, double idleSeconds = 0.1);
  bool closeRequested() const;
  /// The framebuffer size in pixels (it differs from the window's on high-density screens).
  void framebufferSize(int& width, int& height) const;

 private:
  GLFWwindow* m_window = nullptr;
  std::string m_error;
  bool m_initialized = false;
};

}  // namespace stroma::viewer
