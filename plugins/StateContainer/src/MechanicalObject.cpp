// SPDX-License-Identifier: MIT
#include "MechanicalObject.h"

#include <cmath>
#include <numbers>

namespace stroma {

namespace {

Quat rotationFromDegrees(const Vec3d& degrees) {
  const Vec3d r = degrees * (std::numbers::pi / 180.0);
  // About x first, then y, then z.
  return Quat(Eigen::AngleAxisd(r.z(), Vec3d::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3d::UnitY()) *
              Eigen::AngleAxisd(r.x(), Vec3d::UnitX()));
}

void transform(Vec3d& p, const Vec3d& scale, const Quat& q, const Vec3d& t) {
  p = q * p.cwiseProduct(scale) + t;
}
void transform(RigidCoord3& c, const Vec3d& scale, const Quat& q, const Vec3d& t) {
  c.center = q * c.center.cwiseProduct(scale) + t;
  c.orientation = (q * c.orientation).normalized();
}

void flatten(const Vec3d& v, std::vector<double>& out) { out.insert(out.end(), v.data(), v.data() + 3); }
void flatten(const RigidCoord3& c, std::vector<double>& out) {
  flatten(c.center, out);
  out.insert(out.end(), {c.orientation.x(), c.orientation.y(), c.orientation.z(), c.orientation.w()});
}
void flatten(const RigidDeriv3& d, std::vector<double>& out) {
  flatten(d.linear, out);
  flatten(d.angular, out);
}

void scaleCoord(Vec3d& p, double s) { p *= s; }
void scaleCoord(RigidCoord3& c, double s) { c.center *= s; }

}  // namespace

template <class DataTypes>
void MechanicalObject<DataTypes>::init() {
  VecCoord& x = d_position.edit();
  if (x.empty() && d_size.value() > 0) x.assign(static_cast<std::size_t>(d_size.value()), DataTypes::zeroCoord());
  if (d_size.isSet() && d_position.isSet() && static_cast<int>(x.size()) != d_size.value() &&
      !x.empty())
    msgWarning("size=" + std::to_string(d_size.value()) + " differs from the " +
                   std::to_string(x.size()) + " positions given; the positions win",
               "size");
  const Vec3d scale = d_scale3d.value() * d_scale.value();
  const Quat q = rotationFromDegrees(d_rotation.value() +
                                     Vec3d(d_rx.value(), d_ry.value(), d_rz.value()));
  const Vec3d t = d_translation.value() + Vec3d(d_dx.value(), d_dy.value(), d_dz.value());
  const bool identity = scale == Vec3d::Ones() && q.isApprox(Quat::Identity(), 0.0) && t.isZero(0.0);
  if (!identity)
    for (Coord& c : x) transform(c, scale, q, t);

  const std::size_t n = x.size();
  auto sizeDeriv = [&](Data<VecDeriv>& d) {
    if (d.value().size() != n) {
      if (!d.value().empty())
        msgWarning("has " + std::to_string(d.value().size()) + " values for " +
                       std::to_string(n) + " positions; resized with zeros",
                   d.name());
      d.edit().resize(n, DataTypes::zeroDeriv());
    }
  };
  sizeDeriv(d_velocity);
  sizeDeriv(d_force);
  sizeDeriv(d_externalForce);
  sizeDeriv(d_derivX);
  sizeDeriv(d_freeVelocity);
  auto sizeCoord = [&](Data<VecCoord>& d) {
    if (d.value().size() != n) {
      if (!d.value().empty())
        msgError("has " + std::to_string(d.value().size()) + " values for " + std::to_string(n) +
                     " positions",
                 d.name());
      d.setValue(x);
    }
  };
  sizeCoord(d_restPosition);
  sizeCoord(d_freePosition);
  sizeCoord(d_resetPosition);
  if (d_restScale.value() != 1.0)
    for (Coord& c : d_restPosition.edit()) scaleCoord(c, d_restScale.value());
}

template <class DataTypes>
void MechanicalObject<DataTypes>::copyPositions(std::vector<double>& out) const {
  out.clear();
  out.reserve(size() * DataTypes::coordSize);
  for (const Coord& c : d_position.value()) flatten(c, out);
}

template <class DataTypes>
void MechanicalObject<DataTypes>::copyVelocities(std::vector<double>& out) const {
  out.clear();
  out.reserve(size() * DataTypes::derivSize);
  for (const Deriv& d : d_velocity.value()) flatten(d, out);
}

template class MechanicalObject<Vec3Types>;
template class MechanicalObject<Rigid3Types>;

}  // namespace stroma
