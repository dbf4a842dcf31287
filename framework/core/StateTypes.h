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
