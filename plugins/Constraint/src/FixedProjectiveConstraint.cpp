// SPDX-License-Identifier: MIT
#include "FixedProjectiveConstraint.h"

namespace stroma {

void FixedProjectiveConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  if (!mstate()) return;
  const std::size_t n = mstate()->size();
  std::string bad;
  int count = 0;
  for (unsigned i : d_indices.value())
    if (i >= n && count++ < 10) {
      if (!bad.empty()) bad += ' ';
      bad += std::to_string(i);
    }
  if (count)
    msgError(std::to_string(count) + " indices out of range of the " + std::to_string(n) +
                 " points of " + mstate()->path() + ": " + bad + (count > 10 ? " ..." : ""),
             "indices");
  if (!d_fixAll.value() && d_indices.value().empty())
    msgWarning("no index given: nothing is fixed", "indices");
}

template <class F>
void FixedProjectiveConstraint::forEachFixed(std::size_t n, F&& f) const {
  if (d_fixAll.value()) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  for (unsigned i : d_indices.value())
    if (i < n) f(i);  // out-of-range indices were reported at init
}

void FixedProjectiveConstraint::projectResponse(VecDeriv& dx) {
  forEachFixed(dx.size(), [&](std::size_t i) { dx[i].setZero(); });
}

void FixedProjectiveConstraint::projectVelocity(VecDeriv& v, double) {
  forEachFixed(v.size(), [&](std::size_t i) { v[i].setZero(); });
}

void FixedProjectiveConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  forEachFixed(mstate()->size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < 3; ++k) rows.push_back(3 * i + k);
  });
}

}  // namespace stroma
