// SPDX-License-Identifier: MIT
#pragma once

#include "AxisProjectiveConstraint.h"

namespace stroma {

/// Keeps points on the line through `origin` along `direction` (SOFA's LineProjectiveConstraint,
/// formerly ProjectToLineConstraint). With d the unit direction and P = d d^T (AllowedMotion.h):
/// forces, increments and velocities of the points become P v, positions their orthogonal
/// projection o + P (x - o) on the line; the points slide freely along it. A direction along a
/// coordinate axis is exact in an assembled matrix (the two other axes' rows are fixed); an
/// oblique one is not (a warning at the first assembly, and the step's end projection alone
/// enforces it). A zero direction is an error; indices out of range are reported and skipped.
class LineProjectiveConstraint final : public AxisProjectiveConstraint {
 public:
  LineProjectiveConstraint() : AxisProjectiveConstraint("Indices of the points kept on the line.") {}

  Data<Vec3d> d_origin{this, "origin", Vec3d::Zero(), "A point of the line.", {.unit = "m"}};
  Data<Vec3d> d_direction{this, "direction", Vec3d(1, 0, 0),
                          "Direction of the line (any length but zero; normalized)."};
  Data<double> d_drawSize{this, "drawSize", 0.0, "Viewers only."};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (indices refer to points)."};


 private:
  const Data<Vec3d>& axis() const override;
  constraint::AllowedMotion motionAlong(const Vec3d& unit) const override;
  void projectPoints(VecCoord& x) override;
};

}  // namespace stroma
