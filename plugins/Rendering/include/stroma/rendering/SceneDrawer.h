// SPDX-License-Identifier: MIT
// Draws a scene with legacy OpenGL (1.x/2.1 fixed function: immediate mode, fixed lights and
// materials), so that the same code draws in OSMesa's offscreen buffers and in a window's GLX
// context. The caller owns the context: make it current before any call below.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/Types.h"
#include "stroma/rendering/Camera.h"
#include "stroma/rendering/ColorMap.h"
#include "stroma/rendering/DisplayFlags.h"

namespace stroma {
class Node;
class Base;
}  // namespace stroma

namespace stroma::rendering {

/// How to draw, beyond what the scene says.
struct DrawOptions {
  /// Replaces the scene's VisualStyle flags when set (a viewer's toggles).
  std::optional<DisplayFlags> flags;
  /// Colors the bodies by a field: each body with a field (ColorMap.h) is drawn as the surface
  /// of its elements, colored per point, in place of its visual models; a legend (color bar
  /// with the range's numbers) is drawn at the right edge.
  ColorMapKind colorMap = ColorMapKind::none;
  bool legend = true;
};

/// What the last draw() did, for tests, warnings and a viewer's HUD.
struct FrameReport {
  std::size_t triangles = 0;  ///< shaded triangles (visual surfaces, element faces, collision)
  std::size_t lines = 0;      ///< wireframe edges, collision lines, contact segments
  std::size_t points = 0;     ///< state points, fixed points, contact points
  std::size_t visualSurfaces = 0;
  std::size_t contacts = 0;
  bool colorMapped = false;  ///< a field colored something this frame
  double colorMin = 0, colorMax = 0;
  std::string legendMin, legendMax;  ///< the numbers the legend wrote
  /// Where it wrote them (top-left pixels, y downwards) and at what scale (BitmapFont.h), so
  /// that a test can read them back from the picture.
  int legendMinX = 0, legendMinY = 0, legendMaxX = 0, legendMaxY = 0, legendScale = 1;
  std::string colorMapError;  ///< why nothing was colored (no such field)
  std::size_t drawn() const { return triangles + lines + points; }
};

/// The width in pixels that the legend of `kind` takes at the right edge of a width x height
/// picture (numbers of up to 9 characters), for a caller that frames the scene beside it.
int legendWidth(ColorMapKind kind, int width, int height);

/// Draws one scene. Keeps what it learns between frames (textures uploaded, warnings given
/// once) and nothing that a step changes: every draw() reads the scene afresh.
class SceneDrawer {
 public:
  explicit SceneDrawer(Node& root);
  ~SceneDrawer();
  SceneDrawer(const SceneDrawer&) = delete;
  SceneDrawer& operator=(const SceneDrawer&) = delete;

  void setOptions(const DrawOptions& options) { m_options = options; }
  const DrawOptions& options() const { return m_options; }

  /// The flags at the root: the options' when set, else the root's VisualStyle. draw() uses,
  /// for each component, the flags at its node (sceneDisplayFlags: styles nest), or the
  /// options' everywhere when set.
  DisplayFlags effectiveFlags() const;

  /// Background color (r g b a): the scene's BackgroundSetting color, else dark grey-blue.
  Vec4d backgroundColor() const;

  /// Brings the visual models up to date (VisualModel::updateVisual()). draw() calls it; a
  /// caller that needs the surfaces before (a camera fit) may call it first.
  void updateVisuals();

  /// Clears and draws the whole scene in the viewport (0, 0, width, height) of the current
  /// context: background, lights (the scene's LightManager lights, else a headlight), then
  /// what the flags show, then the legend. Leaves the projection and modelview matrices of the
  /// camera loaded (a viewer may draw more in world coordinates after).
  void draw(const Camera& camera, int width, int height);

  const FrameReport& lastFrame() const { return m_report; }

  /// Deletes the textures uploaded to the current context (call before the context goes, or
  /// before drawing into another one).
  void releaseGLResources();

 private:
  /// The flags at each active node, for this frame; their union.
  DisplayFlags collectNodeFlags();
  const DisplayFlags& flagsAt(const Node* node) const;
  void drawColoredBodies();
  void drawVisualModels(const std::set<const Node*>& skipped);
  void drawElementMeshes(const std::set<const Node*>& skipped);
  void drawStates();
  void drawCollisionModels();
  void drawDecorations(const Vec4d& background, int width, int height);

  struct Impl;
  Node& m_root;
  DrawOptions m_options;
  FrameReport m_report;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace stroma::rendering
