// SPDX-License-Identifier: MIT
#include "ViewerWindow.h"

#include <GLFW/glfw3.h>

#include <cstdlib>

#include "SceneViewer.h"

namespace stroma::viewer {

namespace {

// GLFW reports errors through one global callback; the last one explains a failed call.
std::string& lastGlfwError() {
  static std::string text;
  return text;
}

void onGlfwError(int code, const char* description) {
  lastGlfwError() = std::string(description ? description : "unknown error") + " (GLFW error " +
                    std::to_string(code) + ")";
}

SceneViewer* viewerOf(GLFWwindow* window) {
  return static_cast<SceneViewer*>(glfwGetWindowUserPointer(window));
}

// Cursor positions are in screen coordinates; the viewer works in framebuffer pixels.
void toPixels(GLFWwindow* window, double& x, double& y) {
  int w = 0, h = 0, fw = 0, fh = 0;
  glfwGetWindowSize(window, &w, &h);
  glfwGetFramebufferSize(window, &fw, &fh);
  if (w > 0 && h > 0) {
    x *= static_cast<double>(fw) / w;
    y *= static_cast<double>(fh) / h;
  }
}

void onMouseButton(GLFWwindow* window, int button, int action, int mods) {
  if (SceneViewer* v = viewerOf(window)) v->mouseButton(button, action, mods);
}
void onCursor(GLFWwindow* window, double x, double y) {
  toPixels(window, x, y);
  if (SceneViewer* v = viewerOf(window)) v->cursorMoved(x, y);
}
void onScroll(GLFWwindow* window, double, double yOffset) {
  if (SceneViewer* v = viewerOf(window)) v->scrolled(yOffset);
}
void onKey(GLFWwindow* window, int key, int, int action, int mods) {
  if (SceneViewer* v = viewerOf(window)) v->key(key, action, mods);
}
void onFramebufferSize(GLFWwindow* window, int width, int height) {
  if (SceneViewer* v = viewerOf(window)) v->resize(width, height);
}

}  // namespace

ViewerWindow::ViewerWindow(int width, int height, const std::string& title) {
  glfwSetErrorCallback(onGlfwError);
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland)) {
    m_error = "no display: DISPLAY is not set (run it in a desktop session, over ssh -X, or "
              "under xvfb-run; `stroma render` makes pictures without a display)";
    return;
  }
  lastGlfwError().clear();
  if (!glfwInit()) {
    m_error = "cannot start GLFW: " + lastGlfwError();
    return;
  }
  m_initialized = true;
  // Legacy OpenGL (2.1, a compatibility context): the Rendering plugin draws with the fixed
  // function pipeline.
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_SAMPLES, 4);
  m_window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!m_window) {
    m_error = "cannot open a window with an OpenGL 2.1 context: " + lastGlfwError();
    return;
  }
  glfwMakeContextCurrent(m_window);
  glfwSwapInterval(1);
  glfwSetMouseButtonCallback(m_window, onMouseButton);
  glfwSetCursorPosCallback(m_window, onCursor);
  glfwSetScrollCallback(m_window, onScroll);
  glfwSetKeyCallback(m_window, onKey);
  glfwSetFramebufferSizeCallback(m_window, onFramebufferSize);
}

ViewerWindow::~ViewerWindow() {
  if (m_window) glfwDestroyWindow(m_window);
  if (m_initialized) glfwTerminate();
}

void ViewerWindow::attach(SceneViewer* viewer) {
  if (!m_window) return;
  glfwSetWindowUserPointer(m_window, viewer);
  if (!viewer) return;
  int w = 0, h = 0;
  framebufferSize(w, h);
  viewer->resize(w, h);
}

void ViewerWindow::present(bool busy, double idleSeconds) {
  glfwSwapBuffers(m_window);
  if (busy)
    glfwPollEvents();
  else
    glfwWaitEventsTimeout(idleSeconds);
}

bool ViewerWindow::closeRequested() const { return glfwWindowShouldClose(m_window); }

void ViewerWindow::framebufferSize(int& width, int& height) const {
  glfwGetFramebufferSize(m_window, &width, &height);
}

}  // namespace stroma::viewer
