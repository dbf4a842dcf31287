// SPDX-License-Identifier: MIT
// The value types that scenes and components share. One header, so that no component grows
// its own typedef preamble.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

namespace stroma {

template <int N>
using Vec = Eigen::Matrix<double, N, 1>;
using Vec1d = Vec<1>;
using Vec2d = Vec<2>;
using Vec3d = Vec<3>;
using Vec4d = Vec<4>;
using Vec6d = Vec<6>;
using Vec2i = Eigen::Matrix<int, 2, 1>;
using Vec3i = Eigen::Matrix<int, 3, 1>;
using Mat3d = Eigen::Matrix3d;

/// Unit quaternion. Written in scenes as "x y z w", SOFA's order.
using Quat = Eigen::Quaterniond;

/// Coordinates of a rigid frame: position of the origin and orientation.
/// Written as 7 numbers "x y z qx qy qz qw", SOFA's Rigid3d coordinate layout.
struct RigidCoord3 {
  Vec3d center = Vec3d::Zero();
  Quat orientation = Quat::Identity();
  bool operator==(const RigidCoord3& o) const {
    return center == o.center && orientation.coeffs() == o.orientation.coeffs();
  }
};

/// Velocity (or any derivative) of a rigid frame: linear then angular, "vx vy vz wx wy wz".
struct RigidDeriv3 {
  Vec3d linear = Vec3d::Zero();
  Vec3d angular = Vec3d::Zero();
  bool operator==(const RigidDeriv3& o) const {
    return linear == o.linear && angular == o.angular;
  }
};

/// A file named in a scene. `original` is what the scene wrote; `resolved` is the path found
/// by the scene loader (scene folder, then the data search path), empty until resolved or when
/// no file of that name exists.
struct FileName {
  std::string original;
  std::string resolved;
  bool operator==(const FileName& o) const { return original == o.original; }
  /// The path to open: the resolved one when known, otherwise what the scene wrote.
  const std::string& path() const { return resolved.empty() ? original : resolved; }
};

}  // namespace stroma
