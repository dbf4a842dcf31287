// SPDX-License-Identifier: MIT
#include "PlaneForceField.h"

namespace stroma {

namespace {

const Vec3d& centerOf(const Vec3d& x) { return x; }
const Vec3d& centerOf(const RigidCoord3& x) { return x.center; }
Vec3d& linearOf(Vec3d& d) { return d; }
Vec3d& linearOf(RigidDeriv3& d) { return d.linear; }
const Vec3d& linearOf(const Vec3d& d) { return d; }
const Vec3d& linearOf(const RigidDeriv3& d) { return d.linear; }

}  // namespace

template <class DataTypes>
void PlaneForceField<DataTypes>::init() {
  ForceField<DataTypes>::init();
  if (d_normal.value().norm() == 0)
    this->msgError("the normal is zero: expected a direction such as '0 1 0'", "normal");
}

template <class DataTypes>
Vec3d PlaneForceField<DataTypes>::unitNormal() const {
  const double length = d_normal.value().norm();
  return length > 0 ? Vec3d(d_normal.value() / length) : Vec3d::Zero();
}

template <class DataTypes>
template <class F>
void PlaneForceField<DataTypes>::forEachContact(const VecCoord& x, F&& f) const {
  const double length = d_normal.value().norm();
  if (length == 0) return;
  const Vec3d n = d_normal.value() / length;
  const double d = d_d.value() / length;
  const bool bilateral = d_bilateral.value();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double delta = centerOf(x[i]).dot(n) - d;
    if (delta < 0 || bilateral) f(i, delta);
  }
}

template <class DataTypes>
void PlaneForceField<DataTypes>::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                          const VecDeriv& v) {
  const Vec3d n = unitNormal();
  const double k = d_stiffness.value(), c = d_damping.value();
  forEachContact(x, [&](std::size_t i, double delta) {
    linearOf(f[i]) += -k * delta * n + c * delta * linearOf(v[i]);
  });
}

template <class DataTypes>
void PlaneForceField<DataTypes>::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                           const VecDeriv& dx) {
  const Vec3d n = unitNormal();
  const double k = d_stiffness.value(), c = d_damping.value();
  const VecCoord& x = this->mstate()->readCoord(mp.x);
  forEachContact(x, [&](std::size_t i, double delta) {
    const Vec3d& u = linearOf(dx[i]);
    linearOf(df[i]) += -mp.kFactor * k * n.dot(u) * n + mp.bFactor * c * delta * u;
  });
}

template <class DataTypes>
void PlaneForceField<DataTypes>::addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                              std::size_t offset) {
  const Vec3d n = unitNormal();
  const double k = d_stiffness.value(), c = d_damping.value();
  const VecCoord& x = this->mstate()->readCoord(mp.x);
  constexpr std::size_t block = DataTypes::derivSize;
  forEachContact(x, [&](std::size_t i, double delta) {
    const Mat3d K =
        -mp.kFactor * k * n * n.transpose() + mp.bFactor * c * delta * Mat3d::Identity();
    matrix.addBlock(offset + block * i, offset + block * i, K);
  });
}

template <class DataTypes>
double PlaneForceField<DataTypes>::potentialEnergy(const MechanicalParams&,
                                                   const VecCoord& x) const {
  double e = 0;
  forEachContact(x, [&](std::size_t, double delta) { e += delta * delta; });
  return 0.5 * d_stiffness.value() * e;
}

template class PlaneForceField<Vec3Types>;
template class PlaneForceField<Rigid3Types>;

}  // namespace stroma
