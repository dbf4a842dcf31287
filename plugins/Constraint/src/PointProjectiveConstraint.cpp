// SPDX-License-Identifier: MIT
#include "PointProjectiveConstraint.h"

#include "core/IndexChecks.h"

namespace stroma {

void PointProjectiveConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  m_checkedIndices = 0;
  if (!mstate()) return;
  checkIndices();
  if (!d_fixAll.value() && d_indices.value().empty())
    msgWarning("no index given: nothing is constrained", "indices");
}

void PointProjectiveConstraint::checkIndices() {
  if (!mstate() || d_indices.version() == m_checkedIndices) return;
  m_checkedIndices = d_indices.version();
  // Checked first: the message's text allocates, and a linked list may change every step.
  if (constraint::anyOutOfRange(d_indices.value(), mstate()->size()))
    reportIndicesOutOfRange(*this, d_indices.value(), mstate()->size(), "indices",
                            "points of " + mstate()->path());
}

template <class F>
void PointProjectiveConstraint::forEachConstrained(std::size_t n, F&& f) const {
  if (d_fixAll.value()) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  for (unsigned i : d_indices.value())
    if (i < n) f(i);  // out-of-range indices are reported by checkIndices
}

void PointProjectiveConstraint::projectResponse(VecDeriv& dx) {
  forEachConstrained(dx.size(), [&](std::size_t i) { dx[i].setZero(); });
}

void PointProjectiveConstraint::projectVelocity(VecDeriv& v, double) {
  checkIndices();  // every step starts with this projection
  forEachConstrained(v.size(), [&](std::size_t i) { v[i].setZero(); });
}

void PointProjectiveConstraint::projectPosition(VecCoord& x, double) {
  const Vec3d& p = d_point.value();
  forEachConstrained(x.size(), [&](std::size_t i) { x[i] = p; });
}

void PointProjectiveConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  if (!mstate()) return;
  forEachConstrained(mstate()->size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < 3; ++k) rows.push_back(3 * i + k);
  });
}

}  // namespace stroma
