// SPDX-License-Identifier: MIT
#include "DirectionProjectiveConstraint.h"

#include "core/IndexChecks.h"

namespace stroma {

void DirectionProjectiveConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  m_checkedIndices = m_checkedDirection = 0;
  if (!mstate()) return;
  update();
  if (d_indices.value().empty()) msgWarning("no index given: nothing is constrained", "indices");
}

void DirectionProjectiveConstraint::update() {
  if (!mstate()) return;
  if (d_indices.version() != m_checkedIndices) {
    m_checkedIndices = d_indices.version();
    // Checked first: the message's text allocates, and a linked list may change every step.
    if (constraint::anyOutOfRange(d_indices.value(), mstate()->size()))
      reportIndicesOutOfRange(*this, d_indices.value(), mstate()->size(), "indices",
                              "points of " + mstate()->path());
  }
  if (d_direction.version() != m_checkedDirection) {
    m_checkedDirection = d_direction.version();
    Vec3d d;
    if (constraint::unitVector(d_direction.value(), d)) {
      m_motion = constraint::AllowedMotion::alongLine(d);
    } else {
      msgError(
          "the direction is zero (or not finite): give a non-zero vector; the points are "
          "left free",
          "direction");
      m_motion = {};
    }
  }
}

void DirectionProjectiveConstraint::projectResponse(VecDeriv& dx) {
  constraint::projectDerivs(m_motion, d_indices.value(), dx);
}

void DirectionProjectiveConstraint::projectVelocity(VecDeriv& v, double) {
  update();  // every step starts with this projection
  constraint::projectDerivs(m_motion, d_indices.value(), v);
}

void DirectionProjectiveConstraint::projectPosition(VecCoord& x, double) {
  if (!mstate()) return;
  // On the line through each point's rest position.
  const VecCoord& x0 = mstate()->readCoord(VecId::restPosition());
  for (unsigned i : d_indices.value())
    if (i < x.size() && i < x0.size()) x[i] = m_motion.projectPosition(x[i], x0[i]);
}

void DirectionProjectiveConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  if (!mstate()) return;
  if (!constraint::appendFixedRows(m_motion, d_indices.value(), mstate()->size(), rows) &&
      !m_reportedAssembled) {
    m_reportedAssembled = true;
    msgWarning(constraint::kObliqueAssembledWarning, "direction");
  }
}

}  // namespace stroma
