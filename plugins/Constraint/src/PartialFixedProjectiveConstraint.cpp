// SPDX-License-Identifier: MIT
#include "PartialFixedProjectiveConstraint.h"

#include "core/IndexChecks.h"

namespace stroma {

namespace {

// Component k of a derivative, as a number one can zero.
double& component(Vec3d& d, std::size_t k) { return d[static_cast<Eigen::Index>(k)]; }
double& component(RigidDeriv3& d, std::size_t k) {
  return k < 3 ? d.linear[static_cast<Eigen::Index>(k)]
               : d.angular[static_cast<Eigen::Index>(k - 3)];
}

}  // namespace

template <class DataTypes>
void PartialFixedProjectiveConstraint<DataTypes>::init() {
  ProjectiveConstraint<DataTypes>::init();
  if (!this->mstate()) return;
  reportIndicesOutOfRange(*this, d_indices.value(), this->mstate()->size(), "indices",
                          "points of " + this->mstate()->path());
  const auto& directions = d_fixedDirections.value();
  if (!directions.empty() && directions.size() != static_cast<std::size_t>(DataTypes::derivSize))
    this->msgError("expected " + std::to_string(DataTypes::derivSize) + " flags (one per " +
                       std::string(DataTypes::name) + " derivative component), got " +
                       std::to_string(directions.size()),
                   "fixedDirections");
  if (!d_fixAll.value() && d_indices.value().empty())
    this->msgWarning("no index given: nothing is constrained", "indices");
}

template <class DataTypes>
bool PartialFixedProjectiveConstraint<DataTypes>::isFixed(std::size_t k) const {
  const auto& directions = d_fixedDirections.value();
  return directions.size() != static_cast<std::size_t>(DataTypes::derivSize) || directions[k];
}

template <class DataTypes>
template <class F>
void PartialFixedProjectiveConstraint<DataTypes>::forEachConstrained(std::size_t n, F&& f) const {
  if (d_fixAll.value()) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  for (unsigned i : d_indices.value())
    if (i < n) f(i);  // out-of-range indices were reported at init
}

template <class DataTypes>
void PartialFixedProjectiveConstraint<DataTypes>::project(VecDeriv& v) const {
  constexpr std::size_t block = DataTypes::derivSize;
  forEachConstrained(v.size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < block; ++k)
      if (isFixed(k)) component(v[i], k) = 0;
  });
}

template <class DataTypes>
void PartialFixedProjectiveConstraint<DataTypes>::projectResponse(VecDeriv& dx) {
  project(dx);
}

template <class DataTypes>
void PartialFixedProjectiveConstraint<DataTypes>::projectVelocity(VecDeriv& v, double) {
  project(v);
}

template <class DataTypes>
void PartialFixedProjectiveConstraint<DataTypes>::fixedRows(std::vector<std::size_t>& rows) const {
  constexpr std::size_t block = DataTypes::derivSize;
  forEachConstrained(this->mstate()->size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < block; ++k)
      if (isFixed(k)) rows.push_back(block * i + k);
  });
}

template class PartialFixedProjectiveConstraint<Vec3Types>;
template class PartialFixedProjectiveConstraint<Rigid3Types>;

}  // namespace stroma
