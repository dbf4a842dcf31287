// SPDX-License-Identifier: MIT
// The kinds of degrees of freedom: what a position (Coord) and a velocity (Deriv) are, and
// the template name a scene gives them. Note that Eigen vectors are not zeroed by `{}`:
// use zeroCoord()/zeroDeriv(). Components templated on the kind take one of these.
#pragma once

#include "core/Types.h"

namespace stroma {

struct Vec3Types {
  using Coord = Vec3d;
  using Deriv = Vec3d;
  static constexpr const char* name = "Vec3d";
  static constexpr int coordSize = 3;
  static constexpr int derivSize = 3;
  static Coord zeroCoord() { return Coord::Zero(); }
  static Deriv zeroDeriv() { return Deriv::Zero(); }
};

/// Points on a line (SOFA's Vec1d): one coordinate per point.
struct Vec1Types {
  using Coord = Vec1d;
  using Deriv = Vec1d;
  static constexpr const char* name = "Vec1d";
  static constexpr int coordSize = 1;
  static constexpr int derivSize = 1;
  static Coord zeroCoord() { return Coord::Zero(); }
  static Deriv zeroDeriv() { return Deriv::Zero(); }
};

/// Points in a plane (SOFA's Vec2d): x and y per point.
struct Vec2Types {
  using Coord = Vec2d;
  using Deriv = Vec2d;
  static constexpr const char* name = "Vec2d";
  static constexpr int coordSize = 2;
  static constexpr int derivSize = 2;
  static Coord zeroCoord() { return Coord::Zero(); }
  static Deriv zeroDeriv() { return Deriv::Zero(); }
};

struct Rigid3Types {
  using Coord = RigidCoord3;
  using Deriv = RigidDeriv3;
  static constexpr const char* name = "Rigid3d";
  static constexpr int coordSize = 7;  // x y z qx qy qz qw
  static constexpr int derivSize = 6;  // vx vy vz wx wy wz
  static Coord zeroCoord() { return Coord{}; }  // origin, identity orientation
  static Deriv zeroDeriv() { return Deriv{}; }
};

}  // namespace stroma
