// SPDX-License-Identifier: MIT
// The camera a picture of a scene is taken with: pure geometry (no OpenGL call), shared by the
// offscreen renderer (`stroma render`) and the interactive viewer.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "collision/Aabb.h"
#include "core/Types.h"

namespace stroma {
class Node;
}

namespace stroma::rendering {

enum class Projection { perspective, orthographic };

/// A half-line from the eye through a pixel, in world coordinates (direction of unit length).
struct Ray {
  Vec3d origin = Vec3d::Zero();
  Vec3d direction = -Vec3d::UnitZ();
};

/// Where a world point lands in a picture: pixel coordinates (x to the right, y downwards, the
/// centre of the top-left pixel at 0.5 0.5) and OpenGL's depth in [0, 1].
struct PixelPoint {
  double x = 0, y = 0, depth = 0;
  bool inFront = true;  ///< false when the point is behind the eye (perspective)
};

/// SOFA's InteractiveCamera model: the eye turns around the point it looks at.
///
/// `orientation` takes camera axes to world axes: the camera looks along its -z, its y is up
/// on the screen; position() = lookAt + orientation * (0, 0, distance). `fieldOfView` is the
/// vertical angle in degrees (perspective); an orthographic camera shows a view height of
/// 2 distance tan(fieldOfView / 2), so that switching projections keeps the size of what is
/// looked at.
class Camera {
 public:
  Projection projection = Projection::perspective;
  Vec3d lookAt = Vec3d::Zero();
  double distance = 1.0;
  Quat orientation = Quat::Identity();
  double fieldOfView = 45.0;  ///< degrees, vertical
  double zNear = 0.01;
  double zFar = 100.0;

  Vec3d position() const;
  Vec3d forward() const;  ///< unit, from the eye towards lookAt
  Vec3d up() const;       ///< unit, screen up
  Vec3d right() const;    ///< unit, screen right

  /// Puts the eye at `eye` looking at `target`, the screen's up as close to `upHint` as the
  /// view allows (another axis when they are parallel). Returns false, unchanged, when eye and
  /// target coincide.
  bool setEyeAndTarget(const Vec3d& eye, const Vec3d& target, const Vec3d& upHint = Vec3d::UnitY());

  /// Reads the first InteractiveCamera of the scene (depth-first from `root`) by its Data names
  /// (position, orientation, lookAt, distance, fieldOfView, zNear, zFar, projectionType).
  /// Returns false, unchanged, when the scene has none. SOFA writes position and orientation
  /// and lets lookAt/distance follow; when `position` is set and differs from lookAt +
  /// orientation * (0 0 distance), position and orientation win and distance is recomputed
  /// along the view direction from lookAt. A bad value leaves that field as it was and adds a
  /// sentence to `warning`.
  bool readSceneCamera(const Node& root, std::string& warning);

  /// Keeps the orientation and fits the whole `box` in a picture of `aspect` = width / height:
  /// lookAt at its centre, distance such that its bounding sphere fills the narrower field,
  /// near and far planes around it. An empty box gives a unit box at the origin.
  void fitBox(const Aabb& box, double aspect);
  /// The same in a width x height picture whose right `rightMargin` pixels are taken (a
  /// legend): the box is fitted in the rest, its centre in the middle of it. A margin of half
  /// the picture or more is ignored.
  void fitBox(const Aabb& box, int width, int height, int rightMargin);
  /// Near and far planes around `box` as seen from where the camera is (so that an orbit or
  /// a zoom never clips the scene).
  void fitClipPlanes(const Aabb& box);

  /// Turns the eye around lookAt: `dx` radians about the screen's up axis (positive: the eye
  /// moves right), `dy` about its right axis (positive: the eye moves up).
  void orbit(double dx, double dy);
  /// Moves eye and lookAt together along the screen, by fractions of the visible height at the
  /// lookAt distance: positive dx moves the view right (the scene goes left on screen),
  /// positive dy moves it up. A viewer dragging the scene with the mouse passes
  /// (-pixels dx, +pixels dy) / picture height.
  void pan(double dx, double dy);
  /// distance *= factor (factor > 0; < 1 comes closer). The orthographic view height follows.
  void zoom(double factor);

  /// Column-major 4 x 4 matrices as OpenGL's glLoadMatrixd takes them.
  Eigen::Matrix4d viewMatrix() const;
  Eigen::Matrix4d projectionMatrix(double aspect) const;

  /// The pixel of a world point in a width x height picture.
  PixelPoint project(const Vec3d& world, int width, int height) const;
  /// The ray through pixel (x, y) (same pixel convention as project).
  Ray unproject(double x, double y, int width, int height) const;
};

/// Parses "px py pz lx ly lz" (eye then target) into a camera's eye and target. Returns false
/// with `error` on anything else (count, non-numbers, eye = target).
bool parseEyeAndTarget(const std::string& text, Vec3d& eye, Vec3d& target, std::string& error);

}  // namespace stroma::rendering
