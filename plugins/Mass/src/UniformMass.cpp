// SPDX-License-Identifier: MIT
#include "UniformMass.h"

namespace stroma {

void UniformMass::init() {
  Mass<Vec3Types>::init();
  if (!mstate()) return;
  const std::size_t n = mstate()->size();
  std::vector<unsigned> bad;
  for (unsigned i : d_indices.value())
    if (i >= n) bad.push_back(i);
  if (!bad.empty()) {
    std::string list;
    for (unsigned i : bad) {
      if (!list.empty()) list += ' ';
      list += std::to_string(i);
    }
    msgError("indices out of range of the " + std::to_string(n) + " points: " + list, "indices");
  }
  if (d_totalMass.value() == 0 && d_vertexMass.value() == 0)
    msgWarning("vertexMass and totalMass are both 0: the points have no mass", "vertexMass");
}

double UniformMass::pointMass() const {
  if (d_totalMass.value() > 0) {
    const std::size_t count = d_indices.value().empty() ? mstate()->size() : d_indices.value().size();
    return count ? d_totalMass.value() / static_cast<double>(count) : 0.0;
  }
  return d_vertexMass.value();
}

template <class F>
void UniformMass::forEachPoint(std::size_t n, F&& f) const {
  const auto& indices = d_indices.value();
  if (indices.empty()) {
    for (std::size_t i = 0; i < n; ++i) f(i);
  } else {
    for (unsigned i : indices) f(i);
  }
}

void UniformMass::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord&,
                           const VecDeriv&) {
  const Vec3d weight = pointMass() * node()->gravity();
  forEachPoint(f.size(), [&](std::size_t i) { f[i] += weight; });
}

double UniformMass::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  const Vec3d weight = pointMass() * node()->gravity();
  double e = 0;
  forEachPoint(x.size(), [&](std::size_t i) { e -= weight.dot(x[i]); });
  return e;
}

void UniformMass::addMDx(VecDeriv& f, const VecDeriv& dx, double factor) {
  const double m = factor * pointMass();
  forEachPoint(f.size(), [&](std::size_t i) { f[i] += m * dx[i]; });
}

void UniformMass::accFromF(VecDeriv& a, const VecDeriv& f) {
  const double inverse = 1.0 / pointMass();
  forEachPoint(a.size(), [&](std::size_t i) { a[i] = f[i] * inverse; });
}

void UniformMass::addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) {
  const double m = factor * pointMass();
  forEachPoint(mstate()->size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < 3; ++k) matrix.add(offset + 3 * i + k, offset + 3 * i + k, m);
  });
}

double UniformMass::kineticEnergy(const VecDeriv& v) const {
  double e = 0;
  forEachPoint(v.size(), [&](std::size_t i) { e += v[i].squaredNorm(); });
  return 0.5 * pointMass() * e;
}

}  // namespace stroma
