// SPDX-License-Identifier: MIT
#include "PlaneProjectiveConstraint.h"

namespace stroma {

const Data<Vec3d>& PlaneProjectiveConstraint::axis() const { return d_normal; }

constraint::AllowedMotion PlaneProjectiveConstraint::motionAlong(const Vec3d& unit) const {
  return constraint::AllowedMotion::inPlane(unit);
}

void PlaneProjectiveConstraint::projectPoints(VecCoord& x) {
  constraint::projectPositions(motion(), d_origin.value(), d_indices.value(), x);
}

}  // namespace stroma
