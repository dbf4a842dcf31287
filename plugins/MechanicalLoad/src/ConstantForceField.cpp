// SPDX-License-Identifier: MIT
#include "ConstantForceField.h"

namespace stroma {

void ConstantForceField::init() {
  ForceField<Vec3Types>::init();
  if (!mstate()) return;
  const std::size_t n = mstate()->size();
  for (unsigned i : d_indices.value())
    if (i >= n) {
      msgError("index " + std::to_string(i) + " out of range of the " + std::to_string(n) +
                   " points",
               "indices");
      break;
    }
  const auto& forces = d_forces.value();
  const std::size_t count = d_indices.value().empty() ? n : d_indices.value().size();
  if (!forces.empty() && forces.size() != count && forces.size() != 1)
    msgError("has " + std::to_string(forces.size()) + " forces for " + std::to_string(count) +
                 " indices",
             "forces");
}

// f(index, force) for every loaded point.
template <class F>
void ConstantForceField::forEachForce(std::size_t n, F&& f) const {
  const auto& indices = d_indices.value();
  const std::size_t count = indices.empty() ? n : indices.size();
  const auto& forces = d_forces.value();
  const Vec3d share = count ? Vec3d(d_totalForce.value() / static_cast<double>(count))
                            : Vec3d::Zero();
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = indices.empty() ? k : indices[k];
    if (i >= n) continue;
    Vec3d force = d_force.value() + share;
    if (!forces.empty()) force += forces.size() == 1 ? forces[0] : forces[k];
    f(i, force);
  }
}

void ConstantForceField::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord&,
                                  const VecDeriv&) {
  forEachForce(f.size(), [&](std::size_t i, const Vec3d& force) { f[i] += force; });
}

double ConstantForceField::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  double e = 0;
  forEachForce(x.size(), [&](std::size_t i, const Vec3d& force) { e -= force.dot(x[i]); });
  return e;
}

}  // namespace stroma
