// SPDX-License-Identifier: MIT
#include "FixedPlaneProjectiveConstraint.h"

#include <string>

#include "core/IndexChecks.h"

namespace stroma {

void FixedPlaneProjectiveConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  m_checkedIndices = 0;
  m_motion = {};  // identity: nothing constrained until the direction is valid
  if (!mstate()) return;
  Vec3d d;
  if (!constraint::unitVector(d_direction.value(), d)) {
    msgError(
        "the direction is zero (or not finite): give a non-zero vector; the points are "
        "left free",
        "direction");
    return;
  }
  m_motion = constraint::AllowedMotion::inPlane(d);
  if (d_indices.value().empty()) m_selectsAlongDirection = true;
  if (m_selectsAlongDirection) selectAlongDirection(d);
  checkIndices();
  if (d_indices.value().empty())
    msgWarning(m_selectsAlongDirection
                   ? "no point between dmin and dmax along the direction: nothing is constrained"
                   : "no index given: nothing is constrained",
               "indices");
}

void FixedPlaneProjectiveConstraint::selectAlongDirection(const Vec3d& d) {
  const double dmin = d_dmin.value(), dmax = d_dmax.value();
  if (dmin > dmax) {
    msgError("dmin (" + std::to_string(dmin) + ") is above dmax (" + std::to_string(dmax) +
                 "): no point is selected",
             "dmin");
    d_indices.setValue({});
    return;
  }
  // The rest positions: where the body starts (as BoxConstraint).
  const VecCoord& x0 = mstate()->readCoord(VecId::restPosition());
  std::vector<unsigned> selected;
  for (std::size_t i = 0; i < x0.size(); ++i) {
    const double distance = d.dot(x0[i]);
    if (distance >= dmin && distance <= dmax) selected.push_back(static_cast<unsigned>(i));
  }
  d_indices.setValue(std::move(selected));
}

void FixedPlaneProjectiveConstraint::checkIndices() {
  if (!mstate() || d_indices.version() == m_checkedIndices) return;
  m_checkedIndices = d_indices.version();
  // Checked first: the message's text allocates, and a linked list may change every step.
  if (constraint::anyOutOfRange(d_indices.value(), mstate()->size()))
    reportIndicesOutOfRange(*this, d_indices.value(), mstate()->size(), "indices",
                            "points of " + mstate()->path());
}

void FixedPlaneProjectiveConstraint::projectResponse(VecDeriv& dx) {
  constraint::projectDerivs(m_motion, d_indices.value(), dx);
}

void FixedPlaneProjectiveConstraint::projectVelocity(VecDeriv& v, double) {
  checkIndices();  // every step starts with this projection
  constraint::projectDerivs(m_motion, d_indices.value(), v);
}

void FixedPlaneProjectiveConstraint::projectPosition(VecCoord& x, double) {
  if (!mstate()) return;
  const VecCoord& x0 = mstate()->readCoord(VecId::restPosition());
  for (unsigned i : d_indices.value())
    if (i < x.size() && i < x0.size()) x[i] = m_motion.projectPosition(x[i], x0[i]);
}

void FixedPlaneProjectiveConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  if (!mstate()) return;
  if (!constraint::appendFixedRows(m_motion, d_indices.value(), mstate()->size(), rows) &&
      !m_reportedAssembled) {
    m_reportedAssembled = true;
    msgWarning(constraint::kObliqueAssembledWarning, "direction");
  }
}

}  // namespace stroma
