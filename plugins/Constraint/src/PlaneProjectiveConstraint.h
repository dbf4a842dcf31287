// SPDX-License-Identifier: MIT
#pragma once

#include "AxisProjectiveConstraint.h"

namespace stroma {

/// Keeps points on the plane through `origin` with normal `normal` (SOFA's
/// PlaneProjectiveConstraint, formerly ProjectToPlaneConstraint). With n the unit normal and
/// P = I - n n^T (AllowedMotion.h): forces, increments and velocities of the points become P v,
/// positions their orthogonal projection o + P (x - o) on the plane; the points slide freely in
/// it. A normal along a coordinate axis is exact in an assembled matrix (that axis's rows are
/// fixed); an oblique one is not (a warning at the first assembly, and the step's end projection
/// alone enforces it). A zero normal is an error; indices out of range are reported and skipped.
class PlaneProjectiveConstraint final : public AxisProjectiveConstraint {
 public:
  PlaneProjectiveConstraint() : AxisProjectiveConstraint("Indices of the points kept on the plane.") {}

  Data<Vec3d> d_origin{this, "origin", Vec3d::Zero(), "A point of the plane.", {.unit = "m"}};
  Data<Vec3d> d_normal{this, "normal", Vec3d(0, 0, 1),
                       "Normal of the plane (any length but zero; normalized)."};
  Data<double> d_drawSize{this, "drawSize", 0.0, "Viewers only."};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (indices refer to points)."};


 private:
  const Data<Vec3d>& axis() const override;
  constraint::AllowedMotion motionAlong(const Vec3d& unit) const override;
  void projectPoints(VecCoord& x) override;
};

}  // namespace stroma
