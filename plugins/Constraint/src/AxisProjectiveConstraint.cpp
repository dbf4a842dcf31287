// SPDX-License-Identifier: MIT
#include "AxisProjectiveConstraint.h"

#include "core/IndexChecks.h"

namespace stroma {

void AxisProjectiveConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  m_checkedIndices = m_checkedAxis = 0;
  if (!mstate()) return;
  update();
  if (d_indices.value().empty()) msgWarning("no index given: nothing is constrained", "indices");
}

void AxisProjectiveConstraint::update() {
  if (!mstate()) return;
  if (d_indices.version() != m_checkedIndices) {
    m_checkedIndices = d_indices.version();
    // Checked first: the message's text allocates, and a linked list may change every step.
    if (constraint::anyOutOfRange(d_indices.value(), mstate()->size()))
      reportIndicesOutOfRange(*this, d_indices.value(), mstate()->size(), "indices",
                              "points of " + mstate()->path());
  }
  if (axis().version() != m_checkedAxis) {
    m_checkedAxis = axis().version();
    Vec3d unit;
    if (constraint::unitVector(axis().value(), unit)) {
      m_motion = motionAlong(unit);
    } else {
      msgError("the " + axis().name() +
                   " is zero (or not finite): give a non-zero vector; the points are left free",
               axis().name());
      m_motion = {};
    }
  }
}

void AxisProjectiveConstraint::projectResponse(VecDeriv& dx) {
  constraint::projectDerivs(m_motion, d_indices.value(), dx);
}

void AxisProjectiveConstraint::projectVelocity(VecDeriv& v, double) {
  update();  // every step starts with this projection
  constraint::projectDerivs(m_motion, d_indices.value(), v);
}

void AxisProjectiveConstraint::projectPosition(VecCoord& x, double) { projectPoints(x); }

void AxisProjectiveConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  if (!mstate()) return;
  if (!constraint::appendFixedRows(m_motion, d_indices.value(), mstate()->size(), rows) &&
      !m_reportedAssembled) {
    m_reportedAssembled = true;
    msgWarning(constraint::kObliqueAssembledWarning, axis().name());
  }
}

}  // namespace stroma
