// SPDX-License-Identifier: MIT
#include "PlaneProjectiveConstraint.h"

#include "core/IndexChecks.h"

namespace stroma {

void PlaneProjectiveConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  m_checkedIndices = m_checkedNormal = 0;
  if (!mstate()) return;
  update();
  if (d_indices.value().empty()) msgWarning("no index given: nothing is constrained", "indices");
}

void PlaneProjectiveConstraint::update() {
  if (!mstate()) return;
  if (d_indices.version() != m_checkedIndices) {
    m_checkedIndices = d_indices.version();
    // Checked first: the message's text allocates, and a linked list may change every step.
    if (constraint::anyOutOfRange(d_indices.value(), mstate()->size()))
      reportIndicesOutOfRange(*this, d_indices.value(), mstate()->size(), "indices",
                              "points of " + mstate()->path());
  }
  if (d_normal.version() != m_checkedNormal) {
    m_checkedNormal = d_normal.version();
    Vec3d n;
    if (constraint::unitVector(d_normal.value(), n)) {
      m_motion = constraint::AllowedMotion::inPlane(n);
    } else {
      msgError(
          "the normal is zero (or not finite): give a non-zero vector; the points are "
          "left free",
          "normal");
      m_motion = {};
    }
  }
}

void PlaneProjectiveConstraint::projectResponse(VecDeriv& dx) {
  constraint::projectDerivs(m_motion, d_indices.value(), dx);
}

void PlaneProjectiveConstraint::projectVelocity(VecDeriv& v, double) {
  update();  // every step starts with this projection
  constraint::projectDerivs(m_motion, d_indices.value(), v);
}

void PlaneProjectiveConstraint::projectPosition(VecCoord& x, double) {
  constraint::projectPositions(m_motion, d_origin.value(), d_indices.value(), x);
}

void PlaneProjectiveConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  if (!mstate()) return;
  if (!constraint::appendFixedRows(m_motion, d_indices.value(), mstate()->size(), rows) &&
      !m_reportedAssembled) {
    m_reportedAssembled = true;
    msgWarning(constraint::kObliqueAssembledWarning, "normal");
  }
}

}  // namespace stroma
