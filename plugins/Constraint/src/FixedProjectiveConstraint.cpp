// SPDX-License-Identifier: MIT
#include "FixedProjectiveConstraint.h"

#include <algorithm>

#include "core/IndexChecks.h"

namespace stroma {

template <class DataTypes>
void FixedProjectiveConstraint<DataTypes>::init() {
  ProjectiveConstraint<DataTypes>::init();
  if (!this->mstate()) return;
  checkIndices();
  if (!d_fixAll.value() && d_indices.value().empty())
    this->msgWarning("no index given: nothing is fixed", "indices");
}

template <class DataTypes>
void FixedProjectiveConstraint<DataTypes>::checkIndices() {
  if (!this->mstate() || d_indices.version() == m_checkedIndices) return;
  m_checkedIndices = d_indices.version();
  // An engine may give new indices every step: the message is written only when one is bad.
  const std::size_t n = this->mstate()->size();
  const auto& indices = d_indices.value();
  if (std::all_of(indices.begin(), indices.end(), [n](unsigned i) { return i < n; })) return;
  reportIndicesOutOfRange(*this, indices, n, "indices", "points of " + this->mstate()->path());
}

template <class DataTypes>
template <class F>
void FixedProjectiveConstraint<DataTypes>::forEachFixed(std::size_t n, F&& f) const {
  if (d_fixAll.value()) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  for (unsigned i : d_indices.value())
    if (i < n) f(i);  // out-of-range indices are reported by checkIndices
}

template <class DataTypes>
void FixedProjectiveConstraint<DataTypes>::projectResponse(VecDeriv& dx) {
  forEachFixed(dx.size(), [&](std::size_t i) { dx[i] = DataTypes::zeroDeriv(); });
}

template <class DataTypes>
void FixedProjectiveConstraint<DataTypes>::projectVelocity(VecDeriv& v, double) {
  checkIndices();  // every step starts with this projection
  forEachFixed(v.size(), [&](std::size_t i) { v[i] = DataTypes::zeroDeriv(); });
}

template <class DataTypes>
void FixedProjectiveConstraint<DataTypes>::fixedRows(std::vector<std::size_t>& rows) const {
  constexpr std::size_t block = DataTypes::derivSize;
  forEachFixed(this->mstate()->size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < block; ++k) rows.push_back(block * i + k);
  });
}

template class FixedProjectiveConstraint<Vec1Types>;
template class FixedProjectiveConstraint<Vec2Types>;
template class FixedProjectiveConstraint<Vec3Types>;
template class FixedProjectiveConstraint<Rigid3Types>;

}  // namespace stroma
