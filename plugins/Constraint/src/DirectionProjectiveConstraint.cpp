// SPDX-License-Identifier: MIT
#include "DirectionProjectiveConstraint.h"

namespace stroma {

const Data<Vec3d>& DirectionProjectiveConstraint::axis() const { return d_direction; }

constraint::AllowedMotion DirectionProjectiveConstraint::motionAlong(const Vec3d& unit) const {
  return constraint::AllowedMotion::alongLine(unit);
}

void DirectionProjectiveConstraint::projectPoints(VecCoord& x) {
  if (!mstate()) return;
  // On the line through each point's rest position.
  const VecCoord& x0 = mstate()->readCoord(VecId::restPosition());
  for (unsigned i : d_indices.value())
    if (i < x.size() && i < x0.size()) x[i] = motion().projectPosition(x[i], x0[i]);
}

}  // namespace stroma
