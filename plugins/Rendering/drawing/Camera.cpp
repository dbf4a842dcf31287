// SPDX-License-Identifier: MIT
#include "stroma/rendering/Camera.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "SceneReading.h"
#include "core/Base.h"
#include "core/Node.h"

namespace stroma::rendering {

namespace {

constexpr double kPi = 3.14159265358979323846;

double halfAngleTangent(double fieldOfViewDegrees) {
  const double fov = std::clamp(fieldOfViewDegrees, 1e-3, 179.0);
  return std::tan(0.5 * fov * kPi / 180.0);
}

std::vector<Vec3d> corners(const Aabb& box) {
  std::vector<Vec3d> out;
  for (int i = 0; i < 8; ++i)
    out.emplace_back(i & 1 ? box.max.x() : box.min.x(), i & 2 ? box.max.y() : box.min.y(),
                     i & 4 ? box.max.z() : box.min.z());
  return out;
}

Aabb nonEmpty(const Aabb& box) {
  if (!box.empty() && box.min.allFinite() && box.max.allFinite()) return box;
  return Aabb{Vec3d::Constant(-0.5), Vec3d::Constant(0.5)};
}

}  // namespace

Vec3d Camera::position() const { return lookAt + orientation * Vec3d(0, 0, distance); }
Vec3d Camera::forward() const { return orientation * Vec3d(0, 0, -1); }
Vec3d Camera::up() const { return orientation * Vec3d(0, 1, 0); }
Vec3d Camera::right() const { return orientation * Vec3d(1, 0, 0); }

bool Camera::setEyeAndTarget(const Vec3d& eye, const Vec3d& target, const Vec3d& upHint) {
  const Vec3d toTarget = target - eye;
  const double length = toTarget.norm();
  if (!(length > 0) || !std::isfinite(length)) return false;
  const Vec3d f = toTarget / length;
  // The up hint must not be along the view: fall back on another axis.
  Vec3d hint = upHint.norm() > 0 ? upHint.normalized() : Vec3d::UnitY();
  for (const Vec3d& candidate : {hint, Vec3d(Vec3d::UnitZ()), Vec3d(Vec3d::UnitX())}) {
    if (f.cross(candidate).norm() > 1e-6) {
      hint = candidate;
      break;
    }
  }
  const Vec3d r = f.cross(hint).normalized();
  const Vec3d u = r.cross(f);
  Mat3d rotation;
  rotation.col(0) = r;
  rotation.col(1) = u;
  rotation.col(2) = -f;
  orientation = Quat(rotation).normalized();
  lookAt = target;
  distance = length;
  return true;
}

bool Camera::readSceneCamera(const Node& root, std::string& warning) {
  const Base* camera = findByClass(root, "InteractiveCamera");
  if (!camera) return false;
  auto vector3 = [&](const char* name, Vec3d& out) {
    std::vector<double> v;
    if (!readNumbers(*camera, name, v) || v.size() != 3 || !Vec3d(v[0], v[1], v[2]).allFinite()) {
      warning += std::string(" ") + camera->path() + "." + name + " is not 3 numbers;";
      return false;
    }
    out = Vec3d(v[0], v[1], v[2]);
    return true;
  };
  auto number = [&](const char* name, double& out, double min) {
    std::vector<double> v;
    if (!readNumbers(*camera, name, v) || v.size() != 1 || !(v[0] > min) || !std::isfinite(v[0])) {
      warning += std::string(" ") + camera->path() + "." + name + " must be a number above " +
                 std::to_string(min) + ";";
      return false;
    }
    out = v[0];
    return true;
  };
  Vec3d position = this->position(), target = lookAt;
  double dist = distance;
  vector3("position", position);
  vector3("lookAt", target);
  number("distance", dist, 0.0);
  number("fieldOfView", fieldOfView, 0.0);
  number("zNear", zNear, -1e300);
  number("zFar", zFar, -1e300);
  std::vector<double> q;
  bool hasOrientation = false;
  if (readNumbers(*camera, "orientation", q) && q.size() == 4) {
    const Quat read(q[3], q[0], q[1], q[2]);  // scenes write x y z w
    if (read.coeffs().allFinite() && read.norm() > 0) {
      orientation = read.normalized();
      hasOrientation = true;
    }
  }
  if (!hasOrientation) warning += " " + camera->path() + ".orientation is not 4 numbers x y z w;";
  const std::string type = readText(*camera, "projectionType");
  projection = (type == "Orthographic" || type == "orthographic" || type == "1")
                   ? Projection::orthographic
                   : Projection::perspective;

  const bool positionSet = isDataSet(*camera, "position");
  const bool orientationSet = isDataSet(*camera, "orientation");
  const bool lookAtSet = isDataSet(*camera, "lookAt");
  if (positionSet && !orientationSet) {
    // Eye and target given: the orientation follows them.
    if (!setEyeAndTarget(position, target)) {
      warning += " " + camera->path() + ": position equals lookAt;";
      lookAt = target;
      distance = dist;
    }
  } else if (positionSet) {
    // Eye and orientation win; the target is on the view axis, at lookAt's distance if given.
    if (lookAtSet && (target - position).norm() > 0) dist = (target - position).norm();
    distance = dist;
    lookAt = position + forward() * dist;
  } else {
    lookAt = target;
    distance = dist;
  }
  return true;
}

void Camera::fitBox(const Aabb& given, double aspect) {
  const Aabb box = nonEmpty(given);
  if (!(aspect > 0) || !std::isfinite(aspect)) aspect = 1.0;
  lookAt = 0.5 * (box.min + box.max);
  const double tanV = halfAngleTangent(fieldOfView);
  const double tanH = tanV * aspect;
  const Vec3d r = right(), u = up(), back = -forward();
  // The smallest distance from lookAt at which every corner is inside the view.
  double needed = 0;
  for (const Vec3d& corner : corners(box)) {
    const Vec3d d = corner - lookAt;
    const double x = std::abs(d.dot(r)), y = std::abs(d.dot(u)), z = d.dot(back);
    if (projection == Projection::perspective)
      needed = std::max({needed, z + x / tanH, z + y / tanV});
    else
      needed = std::max({needed, x / tanH, y / tanV});
  }
  const double extent = (box.max - box.min).norm();
  // A 5 % margin around the box; never closer than the box's own size allows.
  distance = std::max(1.05 * needed, 1e-3 * std::max(extent, 1e-9));
  if (projection == Projection::perspective) distance = std::max(distance, 0.5 * extent * 1e-3);
  fitClipPlanes(box);
}

void Camera::fitBox(const Aabb& box, int width, int height, int rightMargin) {
  if (width <= 0 || height <= 0) return fitBox(box, 1.0);
  if (rightMargin <= 0 || rightMargin >= width / 2) return fitBox(box, double(width) / height);
  fitBox(box, double(width - rightMargin) / height);
  // Move the view right by half the margin: the box's centre goes left by as many pixels.
  pan(0.5 * rightMargin / height, 0);
}

void Camera::fitClipPlanes(const Aabb& given) {
  const Aabb box = nonEmpty(given);
  const Vec3d eye = position(), f = forward();
  double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
  for (const Vec3d& corner : corners(box)) {
    const double depth = (corner - eye).dot(f);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  const double extent = std::max((box.max - box.min).norm(), 1e-9);
  // Margins of a hundredth of the box, so that a surface on the box's face is not clipped.
  farthest = std::max(farthest, distance) + 0.01 * extent;
  if (projection == Projection::perspective) {
    // Depth precision: the near plane no closer than a thousandth of the far one.
    zNear = std::max(nearest - 0.01 * extent, 1e-3 * farthest);
  } else {
    zNear = nearest - 0.01 * extent;
  }
  zFar = farthest;
}

void Camera::orbit(double dx, double dy) {
  if (!std::isfinite(dx) || !std::isfinite(dy)) return;
  const Quat turn = Eigen::AngleAxisd(dx, up()) * Quat(Eigen::AngleAxisd(-dy, right()));
  orientation = (turn * orientation).normalized();
}

void Camera::pan(double dx, double dy) {
  if (!std::isfinite(dx) || !std::isfinite(dy)) return;
  const double height = 2.0 * distance * halfAngleTangent(fieldOfView);
  lookAt += (right() * dx + up() * dy) * height;
}

void Camera::zoom(double factor) {
  if (factor > 0 && std::isfinite(factor)) distance *= factor;
}

Eigen::Matrix4d Camera::viewMatrix() const {
  const Mat3d rt = orientation.toRotationMatrix().transpose();
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.topLeftCorner<3, 3>() = rt;
  view.topRightCorner<3, 1>() = -rt * position();
  return view;
}

Eigen::Matrix4d Camera::projectionMatrix(double aspect) const {
  if (!(aspect > 0) || !std::isfinite(aspect)) aspect = 1.0;
  const double tanV = halfAngleTangent(fieldOfView);
  const double n = zNear, f = zFar > zNear ? zFar : zNear + 1.0;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  if (projection == Projection::perspective) {
    const double nn = n > 0 ? n : 1e-3 * f;
    p(0, 0) = 1.0 / (tanV * aspect);
    p(1, 1) = 1.0 / tanV;
    p(2, 2) = -(f + nn) / (f - nn);
    p(2, 3) = -2.0 * f * nn / (f - nn);
    p(3, 2) = -1.0;
  } else {
    const double halfH = distance * tanV, halfW = halfH * aspect;
    p(0, 0) = 1.0 / halfW;
    p(1, 1) = 1.0 / halfH;
    p(2, 2) = -2.0 / (f - n);
    p(2, 3) = -(f + n) / (f - n);
    p(3, 3) = 1.0;
  }
  return p;
}

PixelPoint Camera::project(const Vec3d& world, int width, int height) const {
  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
  const Eigen::Vector4d clip = projectionMatrix(aspect) * viewMatrix() * world.homogeneous();
  PixelPoint out;
  out.inFront = clip.w() > 0;
  const double w = clip.w() != 0 ? clip.w() : 1e-300;
  out.x = (clip.x() / w + 1.0) * 0.5 * width;
  out.y = (1.0 - clip.y() / w) * 0.5 * height;
  out.depth = (clip.z() / w + 1.0) * 0.5;
  return out;
}

Ray Camera::unproject(double x, double y, int width, int height) const {
  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
  const double nx = width > 0 ? 2.0 * x / width - 1.0 : 0.0;
  const double ny = height > 0 ? 1.0 - 2.0 * y / height : 0.0;
  const double tanV = halfAngleTangent(fieldOfView);
  Ray ray;
  if (projection == Projection::perspective) {
    ray.origin = position();
    ray.direction = (forward() + right() * (nx * tanV * aspect) + up() * (ny * tanV)).normalized();
  } else {
    const double halfH = distance * tanV, halfW = halfH * aspect;
    ray.origin = position() + right() * (nx * halfW) + up() * (ny * halfH);
    ray.direction = forward();
  }
  return ray;
}

bool parseEyeAndTarget(const std::string& text, Vec3d& eye, Vec3d& target, std::string& error) {
  std::istringstream in(text);
  std::vector<double> v;
  std::string token;
  while (in >> token) {
    try {
      std::size_t used = 0;
      const double value = std::stod(token, &used);
      if (used != token.size() || !std::isfinite(value)) throw std::invalid_argument(token);
      v.push_back(value);
    } catch (const std::exception&) {
      error = "'" + token + "' is not a number";
      return false;
    }
  }
  if (v.size() != 6) {
    error = "expected 6 numbers \"px py pz lx ly lz\" (eye, then the point looked at), got " +
            std::to_string(v.size());
    return false;
  }
  eye = Vec3d(v[0], v[1], v[2]);
  target = Vec3d(v[3], v[4], v[5]);
  if ((eye - target).norm() == 0) {
    error = "the eye and the point looked at are the same point";
    return false;
  }
  return true;
}

}  // namespace stroma::rendering
