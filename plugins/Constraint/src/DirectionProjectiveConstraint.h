// SPDX-License-Identifier: MIT
#pragma once

#include "AxisProjectiveConstraint.h"

namespace stroma {

/// Lets points move only along `direction` (SOFA's DirectionProjectiveConstraint, formerly
/// ProjectDirectionConstraint): each point stays on the line through its rest position along
/// the direction. With d the unit direction and P = d d^T (AllowedMotion.h): forces, increments
/// and velocities of the points become P v, positions x0 + P (x - x0) (x0 the rest position).
/// A direction along a coordinate axis is exact in an assembled matrix (the two other axes'
/// rows are fixed); an oblique one is not (a warning at the first assembly, and the step's end
/// projection alone enforces it). A zero direction is an error; indices out of range are
/// reported and skipped.
class DirectionProjectiveConstraint final : public AxisProjectiveConstraint {
 public:
  DirectionProjectiveConstraint()
      : AxisProjectiveConstraint("Indices of the points that move along the direction.") {}

  Data<Vec3d> d_direction{this, "direction", Vec3d(1, 0, 0),
                          "Direction of the allowed motion (any length but zero; normalized)."};
  Data<double> d_drawSize{this, "drawSize", 0.0, "Viewers only."};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (indices refer to points)."};


 private:
  const Data<Vec3d>& axis() const override;
  constraint::AllowedMotion motionAlong(const Vec3d& unit) const override;
  void projectPoints(VecCoord& x) override;
};

}  // namespace stroma
