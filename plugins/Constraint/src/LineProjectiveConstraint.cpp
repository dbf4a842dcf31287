// SPDX-License-Identifier: MIT
#include "LineProjectiveConstraint.h"

namespace stroma {

const Data<Vec3d>& LineProjectiveConstraint::axis() const { return d_direction; }

constraint::AllowedMotion LineProjectiveConstraint::motionAlong(const Vec3d& unit) const {
  return constraint::AllowedMotion::alongLine(unit);
}

void LineProjectiveConstraint::projectPoints(VecCoord& x) {
  constraint::projectPositions(motion(), d_origin.value(), d_indices.value(), x);
}

}  // namespace stroma
