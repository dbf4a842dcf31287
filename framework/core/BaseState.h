// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Base.h"

namespace stroma {

/// The kernel's view of a set of degrees of freedom (a MechanicalObject): enough to pick
/// component templates from the context and to export and compare states. Mechanical
/// operations use the richer interface of the mechanics plugins.
class BaseState : public Base {
 public:
  /// Number of degrees of freedom (points or frames).
  virtual std::size_t size() const = 0;
  /// Numbers per position (3 for Vec3d, 7 for Rigid3d: x y z qx qy qz qw).
  virtual int coordDimension() const = 0;
  /// Numbers per velocity (3 for Vec3d, 6 for Rigid3d: linear then angular).
  virtual int derivDimension() const = 0;
  /// Positions and velocities, flattened (size() * dimension numbers).
  virtual void copyPositions(std::vector<double>& out) const = 0;
  virtual void copyVelocities(std::vector<double>& out) const = 0;
};

}  // namespace stroma
