// SPDX-License-Identifier: MIT
#include "ConstantForceField.h"

#include "core/IndexChecks.h"

namespace stroma {

namespace {

template <int N>
Vec<N> scaled(const Vec<N>& d, double s) {
  return s * d;
}
RigidDeriv3 scaled(const RigidDeriv3& d, double s) { return {s * d.linear, s * d.angular}; }
template <int N>
void accumulate(Vec<N>& to, const Vec<N>& d) {
  to += d;
}
void accumulate(RigidDeriv3& to, const RigidDeriv3& d) {
  to.linear += d.linear;
  to.angular += d.angular;
}
template <int N>
double work(const Vec<N>& f, const Vec<N>& x) {
  return f.dot(x);
}
double work(const RigidDeriv3& f, const RigidCoord3& x) { return f.linear.dot(x.center); }

}  // namespace

template <class DataTypes>
void ConstantForceField<DataTypes>::init() {
  ForceField<DataTypes>::init();
  if (!this->mstate()) return;
  const std::size_t n = this->mstate()->size();
  reportIndicesOutOfRange(*this, d_indices.value(), n, "indices");
  const auto& forces = d_forces.value();
  const std::size_t count = d_indices.value().empty() ? n : d_indices.value().size();
  if (!forces.empty() && forces.size() != count && forces.size() != 1)
    this->msgError("has " + std::to_string(forces.size()) + " forces for " + std::to_string(count) +
                       " indices",
                   "forces");
}

// f(index, force) for every loaded point.
template <class DataTypes>
template <class F>
void ConstantForceField<DataTypes>::forEachForce(std::size_t n, F&& f) const {
  const auto& indices = d_indices.value();
  const std::size_t count = indices.empty() ? n : indices.size();
  const auto& forces = d_forces.value();
  const Deriv share = scaled(d_totalForce.value(), count ? 1.0 / static_cast<double>(count) : 0.0);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = indices.empty() ? k : indices[k];
    if (i >= n) continue;
    Deriv force = d_force.value();
    accumulate(force, share);
    if (!forces.empty()) accumulate(force, forces.size() == 1 ? forces[0] : forces[k]);
    f(i, force);
  }
}

template <class DataTypes>
void ConstantForceField<DataTypes>::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord&,
                                             const VecDeriv&) {
  forEachForce(f.size(), [&](std::size_t i, const Deriv& force) { accumulate(f[i], force); });
}

template <class DataTypes>
double ConstantForceField<DataTypes>::potentialEnergy(const MechanicalParams&,
                                                      const VecCoord& x) const {
  double e = 0;
  forEachForce(x.size(), [&](std::size_t i, const Deriv& force) { e -= work(force, x[i]); });
  return e;
}

template class ConstantForceField<Vec1Types>;
template class ConstantForceField<Vec2Types>;
template class ConstantForceField<Vec3Types>;
template class ConstantForceField<Rigid3Types>;

}  // namespace stroma
