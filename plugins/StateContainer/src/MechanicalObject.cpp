// SPDX-License-Identifier: MIT
#include "MechanicalObject.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/Node.h"
#include "topology/Topology.h"

namespace stroma {

namespace {

Quat rotationFromDegrees(const Vec3d& degrees) {
  const Vec3d r = degrees * (std::numbers::pi / 180.0);
  // About x first, then y, then z.
  return Quat(Eigen::AngleAxisd(r.z(), Vec3d::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3d::UnitY()) *
              Eigen::AngleAxisd(r.x(), Vec3d::UnitX()));
}

// Points of fewer than 3 coordinates are transformed in 3D (missing coordinates 0) and keep
// their first N coordinates, as SOFA does.
template <int N>
void transform(Vec<N>& p, const Vec3d& scale, const Quat& q, const Vec3d& t) {
  Vec3d p3 = Vec3d::Zero();
  p3.head<N>() = p;
  p = (q * p3.cwiseProduct(scale) + t).head<N>();
}
void transform(RigidCoord3& c, const Vec3d& scale, const Quat& q, const Vec3d& t) {
  c.center = q * c.center.cwiseProduct(scale) + t;
  c.orientation = (q * c.orientation).normalized();
}

template <int N>
void flatten(const Vec<N>& v, std::vector<double>& out) {
  out.insert(out.end(), v.data(), v.data() + N);
}
void flatten(const RigidCoord3& c, std::vector<double>& out) {
  flatten(c.center, out);
  out.insert(out.end(), {c.orientation.x(), c.orientation.y(), c.orientation.z(), c.orientation.w()});
}
void flatten(const RigidDeriv3& d, std::vector<double>& out) {
  flatten(d.linear, out);
  flatten(d.angular, out);
}

template <int N>
void scaleCoord(Vec<N>& p, double s) {
  p *= s;
}
void scaleCoord(RigidCoord3& c, double s) { c.center *= s; }

}  // namespace

template <class DataTypes>
void MechanicalObject<DataTypes>::init() {
  // As SOFA: a state given neither positions nor a size takes the points of the topology in
  // its node (a RegularGridTopology, a container that took a loader's points). Topology points
  // are 3D: a Vec1d or Vec2d state keeps their first 1 or 2 coordinates.
  if constexpr (!std::is_same_v<DataTypes, Rigid3Types>) {
    if (d_position.value().empty() && d_size.value() == 0 && this->node())
      if (const Topology* topology = this->node()->template get<Topology>())
        if (!topology->positions().empty()) {
          VecCoord points;
          points.reserve(topology->positions().size());
          for (const Vec3d& p : topology->positions())
            points.push_back(p.head<DataTypes::coordSize>());
          d_position.setValue(std::move(points));
        }
  }
  // As SOFA, whose constructor makes one degree of freedom: a state given nothing that sizes it
  // (no positions, size, rest positions or topology points) has one, at the origin. SOFA's
  // scenes rely on it for a rigid body's frame (`<MechanicalObject template="Rigid3d"/>` with a
  // RigidMapping below) and for a lone particle.
  const bool sized = !d_position.value().empty() || d_position.isSet() || d_size.isSet() ||
                     !d_restPosition.value().empty();
  VecCoord& x = d_position.edit();
  if (!sized) x.assign(1, DataTypes::zeroCoord());
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
  sizeDeriv(d_constraintForce);
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

// Vector storage by id.
template <class DataTypes>
Data<typename MechanicalObject<DataTypes>::VecCoord>* MechanicalObject<DataTypes>::coordData(
    int index) {
  switch (index) {
    case 0: return &d_position;
    case 1: return &d_restPosition;
    case 2: return &d_freePosition;
    case 3: return &d_resetPosition;
    default: return nullptr;
  }
}

template <class DataTypes>
Data<typename MechanicalObject<DataTypes>::VecDeriv>* MechanicalObject<DataTypes>::derivData(
    int index) {
  switch (index) {
    case 0: return &d_velocity;
    case 1: return &d_force;
    case 2: return &d_derivX;
    case 3: return &d_freeVelocity;
    case 4: return &d_externalForce;
    case 5: return &d_constraintForce;
    default: return nullptr;
  }
}

namespace {
template <class T>
T& temporary(std::vector<std::unique_ptr<T>>& temps, int index, std::size_t n, bool create) {
  const auto k = static_cast<std::size_t>(index - VecId::kFirstTemporary);
  if (k >= temps.size()) temps.resize(k + 1);
  if (!temps[k]) {
    if (!create) throw std::logic_error("state vector " + std::to_string(index) + " not allocated");
    temps[k] = std::make_unique<T>();
  }
  if (temps[k]->size() != n) temps[k]->resize(n);
  return *temps[k];
}
}  // namespace

template <class DataTypes>
const typename MechanicalObject<DataTypes>::VecCoord& MechanicalObject<DataTypes>::readCoord(
    VecId v) const {
  return const_cast<MechanicalObject*>(this)->writeCoord(v);
}

template <class DataTypes>
typename MechanicalObject<DataTypes>::VecCoord& MechanicalObject<DataTypes>::writeCoord(VecId v) {
  if (Data<VecCoord>* d = coordData(v.index)) return d->edit();
  return temporary(m_tempCoords, v.index, size(), false);
}

template <class DataTypes>
const typename MechanicalObject<DataTypes>::VecDeriv& MechanicalObject<DataTypes>::readDeriv(
    VecId v) const {
  return const_cast<MechanicalObject*>(this)->writeDeriv(v);
}

template <class DataTypes>
typename MechanicalObject<DataTypes>::VecDeriv& MechanicalObject<DataTypes>::writeDeriv(VecId v) {
  return derivOfSize(v, size());
}

template <class DataTypes>
typename MechanicalObject<DataTypes>::VecDeriv& MechanicalObject<DataTypes>::derivOfSize(
    VecId v, std::size_t n) {
  if (Data<VecDeriv>* d = derivData(v.index)) {
    VecDeriv& values = d->edit();
    if (values.size() != n) values.resize(n, DataTypes::zeroDeriv());
    return values;
  }
  return temporary(m_tempDerivs, v.index, n, false);
}

template <class DataTypes>
void MechanicalObject<DataTypes>::vAlloc(VecId v) {
  if (v.isCoord() && !coordData(v.index)) {
    VecCoord& c = temporary(m_tempCoords, v.index, size(), true);
    std::fill(c.begin(), c.end(), DataTypes::zeroCoord());
  } else if (v.isDeriv() && !derivData(v.index)) {
    VecDeriv& d = temporary(m_tempDerivs, v.index, size(), true);
    std::fill(d.begin(), d.end(), DataTypes::zeroDeriv());
  }
}

template <class DataTypes>
void MechanicalObject<DataTypes>::vFree(VecId) {
  // Temporaries keep their storage for the next step (no allocation per step).
}

namespace {

// Element operations. Vec1d, Vec2d, Vec3d: plain vectors. Rigid: center and orientation; an
// increment's angular part is a rotation vector.
template <int N>
void combine(Vec<N>& out, const Vec<N>* a, const Vec<N>* b, double f) {
  out = (a ? *a : Vec<N>::Zero()) + (b ? Vec<N>(*b * f) : Vec<N>::Zero());
}
void combine(RigidDeriv3& out, const RigidDeriv3* a, const RigidDeriv3* b, double f) {
  RigidDeriv3 r;
  if (a) r = *a;
  if (b) {
    r.linear += b->linear * f;
    r.angular += b->angular * f;
  }
  out = r;
}
template <int N>
void integrate(Vec<N>& out, const Vec<N>* a, const Vec<N>* b, double f) {
  combine(out, a, b, f);
}
void integrate(RigidCoord3& out, const RigidCoord3* a, const RigidDeriv3* b, double f) {
  RigidCoord3 r;
  if (a) r = *a;
  if (b) {
    r.center += b->linear * f;
    const Vec3d w = b->angular * f;
    const double angle = w.norm();
    if (angle > 0) r.orientation = (Quat(Eigen::AngleAxisd(angle, w / angle)) * r.orientation).normalized();
  }
  out = r;
}
// coord = a + b f with both coords: positions add; a rigid orientation is copied from a.
template <int N>
void combineCoords(Vec<N>& out, const Vec<N>* a, const Vec<N>* b, double f) {
  combine(out, a, b, f);
}
void combineCoords(RigidCoord3& out, const RigidCoord3* a, const RigidCoord3* b, double f) {
  RigidCoord3 r;
  if (a) r = *a;
  if (b) r.center += b->center * f;
  out = r;
}
template <int N>
double dotOf(const Vec<N>& a, const Vec<N>& b) {
  return a.dot(b);
}
double dotOf(const RigidDeriv3& a, const RigidDeriv3& b) {
  return a.linear.dot(b.linear) + a.angular.dot(b.angular);
}
template <int N>
void toNumbers(const Vec<N>& d, double* out) {
  std::copy(d.data(), d.data() + N, out);
}
void toNumbers(const RigidDeriv3& d, double* out) {
  std::copy(d.linear.data(), d.linear.data() + 3, out);
  std::copy(d.angular.data(), d.angular.data() + 3, out + 3);
}
template <int N>
void fromNumbers(const double* in, Vec<N>& d) {
  d = Eigen::Map<const Vec<N>>(in);
}
void fromNumbers(const double* in, RigidDeriv3& d) {
  d.linear = Vec3d(in[0], in[1], in[2]);
  d.angular = Vec3d(in[3], in[4], in[5]);
}

}  // namespace

template <class DataTypes>
void MechanicalObject<DataTypes>::vOp(VecId v, VecId a, VecId b, double f) {
  // size() once: it reads the positions, through their links (the loader's inputs checked).
  const std::size_t n = size();
  if (v.isDeriv()) {
    VecDeriv& out = derivOfSize(v, n);
    const VecDeriv* va = a.isNull() ? nullptr : &derivOfSize(a, n);
    const VecDeriv* vb = b.isNull() ? nullptr : &derivOfSize(b, n);
    for (std::size_t i = 0; i < n; ++i)
      combine(out[i], va ? &(*va)[i] : nullptr, vb ? &(*vb)[i] : nullptr, f);
    return;
  }
  VecCoord& out = writeCoord(v);
  const VecCoord* va = a.isNull() ? nullptr : &readCoord(a);
  if (b.isDeriv()) {
    const VecDeriv& vb = derivOfSize(b, n);
    for (std::size_t i = 0; i < n; ++i) integrate(out[i], va ? &(*va)[i] : nullptr, &vb[i], f);
  } else {
    const VecCoord* vb = b.isNull() ? nullptr : &readCoord(b);
    for (std::size_t i = 0; i < n; ++i)
      combineCoords(out[i], va ? &(*va)[i] : nullptr, vb ? &(*vb)[i] : nullptr, f);
  }
}

template <class DataTypes>
double MechanicalObject<DataTypes>::vDot(VecId a, VecId b) const {
  auto& self = const_cast<MechanicalObject&>(*this);
  const std::size_t n = size();
  const VecDeriv& va = self.derivOfSize(a, n);
  const VecDeriv& vb = self.derivOfSize(b, n);
  double sum = 0;
  for (std::size_t i = 0; i < va.size(); ++i) sum += dotOf(va[i], vb[i]);
  return sum;
}

template <class DataTypes>
double MechanicalObject<DataTypes>::vMaxAbs(VecId a, std::size_t& where) const {
  std::vector<double>& numbers = m_scratch;  // reused: no allocation per step
  numbers.clear();
  if (a.isCoord()) {
    for (const Coord& c : readCoord(a)) flatten(c, numbers);
  } else {
    for (const Deriv& d : readDeriv(a)) flatten(d, numbers);
  }
  const std::size_t per = a.isCoord() ? DataTypes::coordSize : DataTypes::derivSize;
  double worst = 0;
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    if (!std::isfinite(numbers[k])) {
      where = k / per;
      return numbers[k];
    }
    if (std::abs(numbers[k]) > worst) {
      worst = std::abs(numbers[k]);
      where = k / per;
    }
  }
  return worst;
}

template <class DataTypes>
void MechanicalObject<DataTypes>::copyToGlobal(VecId v, Eigen::Ref<Eigen::VectorXd> g,
                                               std::size_t offset) const {
  const VecDeriv& d = readDeriv(v);
  for (std::size_t i = 0; i < d.size(); ++i)
    toNumbers(d[i], g.data() + offset + i * DataTypes::derivSize);
}

template <class DataTypes>
void MechanicalObject<DataTypes>::copyFromGlobal(VecId v, const Eigen::Ref<const Eigen::VectorXd>& g,
                                                 std::size_t offset) {
  VecDeriv& d = writeDeriv(v);
  for (std::size_t i = 0; i < d.size(); ++i)
    fromNumbers(g.data() + offset + i * DataTypes::derivSize, d[i]);
}

template class MechanicalObject<Vec1Types>;
template class MechanicalObject<Vec2Types>;
template class MechanicalObject<Vec3Types>;
template class MechanicalObject<Rigid3Types>;

}  // namespace stroma
