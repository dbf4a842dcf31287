// SPDX-License-Identifier: MIT
#include "UniformMass.h"

#include <Eigen/LU>

#include "core/IndexChecks.h"
#include "core/Node.h"

namespace stroma {

namespace {

// World inertia m R J R^T of a frame (J per unit mass, body frame).
Mat3d worldInertia(const RigidMass3& m, const Quat& orientation) {
  const Mat3d R = orientation.normalized().toRotationMatrix();
  return R * m.bodyInertia() * R.transpose();
}

}  // namespace

template <class DataTypes>
void UniformMass<DataTypes>::init() {
  Mass<DataTypes>::init();
  if (!this->mstate()) return;
  const std::size_t n = this->mstate()->size();
  reportIndicesOutOfRange(*this, d_indices.value(), n, "indices");
  if (d_filename.isSet() && !d_filename.value().original.empty())
    this->msgError("mass files (" + d_filename.value().original +
                       ") are not supported: give vertexMass or totalMass instead",
                   "filename");
  const double mass = [&] {
    if constexpr (kRigid)
      return d_vertexMass.value().mass;
    else
      return d_vertexMass.value();
  }();
  if (d_totalMass.value() == 0 && mass == 0)
    this->msgWarning("vertexMass and totalMass are both 0: the points have no mass", "vertexMass");
  if constexpr (kRigid) {
    const Mat3d J = d_vertexMass.value().inertia;
    if (J.determinant() <= 0 || J.diagonal().minCoeff() <= 0)
      this->msgError(
          "the inertia matrix per unit mass must be positive definite (got a "
          "determinant of " +
              std::to_string(J.determinant()) + ")",
          "vertexMass");
  }
}

template <class DataTypes>
auto UniformMass<DataTypes>::pointMass() const -> MassType {
  MassType m = d_vertexMass.value();
  if (d_totalMass.value() > 0) {
    const std::size_t count =
        d_indices.value().empty() ? this->mstate()->size() : d_indices.value().size();
    const double share = count ? d_totalMass.value() / static_cast<double>(count) : 0.0;
    if constexpr (kRigid)
      m.mass = share;
    else
      m = share;
  }
  return m;
}

template <class DataTypes>
template <class F>
void UniformMass<DataTypes>::forEachPoint(std::size_t n, F&& f) const {
  const auto& indices = d_indices.value();
  if (indices.empty()) {
    for (std::size_t i = 0; i < n; ++i) f(i);
  } else {
    for (unsigned i : indices)
      if (i < n) f(i);  // out-of-range indices were reported at init
  }
}

template <class DataTypes>
void UniformMass<DataTypes>::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord&,
                                      const VecDeriv&) {
  const MassType m = pointMass();
  const Vec3d g = this->node()->gravity();
  if constexpr (kRigid) {
    const Vec3d weight = m.mass * g;
    forEachPoint(f.size(), [&](std::size_t i) { f[i].linear += weight; });
  } else {
    // Points of 1 or 2 coordinates take the first components of the gravity, as SOFA does.
    const Vec<DataTypes::derivSize> weight = m * g.head<DataTypes::derivSize>();
    forEachPoint(f.size(), [&](std::size_t i) { f[i] += weight; });
  }
}

template <class DataTypes>
double UniformMass<DataTypes>::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  const MassType m = pointMass();
  const Vec3d g = this->node()->gravity();
  double e = 0;
  if constexpr (kRigid) {
    forEachPoint(x.size(), [&](std::size_t i) { e -= m.mass * g.dot(x[i].center); });
  } else {
    const Vec<DataTypes::coordSize> gravity = g.head<DataTypes::coordSize>();
    forEachPoint(x.size(), [&](std::size_t i) { e -= m * gravity.dot(x[i]); });
  }
  return e;
}

template <class DataTypes>
void UniformMass<DataTypes>::addMDx(VecDeriv& f, const VecDeriv& dx, double factor) {
  const MassType m = pointMass();
  if constexpr (kRigid) {
    const VecCoord& x = this->mstate()->readCoord(VecId::position());
    forEachPoint(f.size(), [&](std::size_t i) {
      f[i].linear += factor * m.mass * dx[i].linear;
      f[i].angular += factor * (worldInertia(m, x[i].orientation) * dx[i].angular);
    });
  } else {
    const double s = factor * m;
    forEachPoint(f.size(), [&](std::size_t i) { f[i] += s * dx[i]; });
  }
}

template <class DataTypes>
void UniformMass<DataTypes>::accFromF(VecDeriv& a, const VecDeriv& f) {
  const MassType m = pointMass();
  if constexpr (kRigid) {
    const VecCoord& x = this->mstate()->readCoord(VecId::position());
    forEachPoint(a.size(), [&](std::size_t i) {
      a[i].linear = f[i].linear / m.mass;
      a[i].angular = worldInertia(m, x[i].orientation).inverse() * f[i].angular;
    });
  } else {
    const double inverse = 1.0 / m;
    forEachPoint(a.size(), [&](std::size_t i) { a[i] = f[i] * inverse; });
  }
}

template <class DataTypes>
void UniformMass<DataTypes>::addMToMatrix(MatrixAccumulator& matrix, std::size_t offset,
                                          double factor) {
  const MassType m = pointMass();
  constexpr std::size_t block = DataTypes::derivSize;
  if constexpr (kRigid) {
    const VecCoord& x = this->mstate()->readCoord(VecId::position());
    forEachPoint(x.size(), [&](std::size_t i) {
      const std::size_t row = offset + block * i;
      for (std::size_t k = 0; k < 3; ++k) matrix.add(row + k, row + k, factor * m.mass);
      matrix.addBlock(row + 3, row + 3, factor * worldInertia(m, x[i].orientation));
    });
  } else {
    const double s = factor * m;
    forEachPoint(this->mstate()->size(), [&](std::size_t i) {
      for (std::size_t k = 0; k < block; ++k)
        matrix.add(offset + block * i + k, offset + block * i + k, s);
    });
  }
}

template <class DataTypes>
double UniformMass<DataTypes>::kineticEnergy(const VecDeriv& v) const {
  const MassType m = pointMass();
  double e = 0;
  if constexpr (kRigid) {
    const VecCoord& x = this->mstate()->readCoord(VecId::position());
    forEachPoint(v.size(), [&](std::size_t i) {
      e += m.mass * v[i].linear.squaredNorm() +
           v[i].angular.dot(worldInertia(m, x[i].orientation) * v[i].angular);
    });
  } else {
    forEachPoint(v.size(), [&](std::size_t i) { e += m * v[i].squaredNorm(); });
  }
  return 0.5 * e;
}

template class UniformMass<Vec1Types>;
template class UniformMass<Vec2Types>;
template class UniformMass<Vec3Types>;
template class UniformMass<Rigid3Types>;

}  // namespace stroma
