// SPDX-License-Identifier: MIT
#include "LinearMovementProjectiveConstraint.h"

#include <algorithm>
#include <cmath>

#include "core/IndexChecks.h"
#include "core/Node.h"

namespace stroma {

namespace {

// SOFA's Euler angles: R = Rz(a[2]) Ry(a[1]) Rx(a[0]).
Quat quatFromEuler(const Vec3d& a) {
  return Quat(Eigen::AngleAxisd(a[2], Vec3d::UnitZ()) * Eigen::AngleAxisd(a[1], Vec3d::UnitY()) *
              Eigen::AngleAxisd(a[0], Vec3d::UnitX()));
}

// The rotation vector of the rotation from a to b, expressed in the world frame (b a^-1).
Vec3d rotationVector(const Quat& a, const Quat& b) {
  const Eigen::AngleAxisd r(b * a.conjugate());
  double angle = r.angle();
  if (angle > M_PI) angle -= 2 * M_PI;  // shortest way round
  return angle * r.axis();
}

}  // namespace

template <class DataTypes>
void LinearMovementProjectiveConstraint<DataTypes>::init() {
  ProjectiveConstraint<DataTypes>::init();
  if (!this->mstate()) return;
  const std::size_t n = this->mstate()->size();
  reportIndicesOutOfRange(*this, d_indices.value(), n, "indices",
                          "points of " + this->mstate()->path());
  const auto& times = d_keyTimes.value();
  if (d_movements.value().size() != times.size())
    this->msgError("has " + std::to_string(d_movements.value().size()) + " movements for " +
                       std::to_string(times.size()) + " key times: give one movement per key time",
                   "movements");
  for (std::size_t k = 1; k < times.size(); ++k)
    if (times[k] < times[k - 1]) {
      this->msgError("key times must be in increasing order: keyTimes[" + std::to_string(k) +
                         "] = " + std::to_string(times[k]) + " < keyTimes[" +
                         std::to_string(k - 1) + "] = " + std::to_string(times[k - 1]),
                     "keyTimes");
      break;
    }
  if (times.size() < 2)
    this->msgWarning("fewer than two key times: nothing is imposed", "keyTimes");
  m_x0 = this->mstate()->readCoord(VecId::position());
}

template <class DataTypes>
bool LinearMovementProjectiveConstraint<DataTypes>::isActive(double t) const {
  const auto& times = d_keyTimes.value();
  return times.size() >= 2 && d_movements.value().size() == times.size() && t >= times.front() &&
         t < times.back();
}

template <class DataTypes>
template <class F>
void LinearMovementProjectiveConstraint<DataTypes>::forEachMoved(std::size_t n, F&& f) const {
  for (unsigned i : d_indices.value())
    if (i < n && i < m_x0.size()) f(i);  // out-of-range indices were reported at init
}

template <class DataTypes>
auto LinearMovementProjectiveConstraint<DataTypes>::positionAt(std::size_t index, double t) const
    -> Coord {
  const auto& times = d_keyTimes.value();
  const auto& moves = d_movements.value();
  // The segment [k, k + 1] holding t (t clamped to the key times), and where in it.
  std::size_t k = 0;
  double s = 0;
  if (times.size() >= 2 && t >= times.back()) {
    k = times.size() - 2;
    s = 1;
  } else if (times.size() >= 2 && t > times.front()) {
    k = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) -
        1;
    const double span = times[k + 1] - times[k];
    s = span > 0 ? (t - times[k]) / span : 1.0;
  }
  const Deriv& a = moves[k];
  const Deriv& b = moves[std::min(k + 1, moves.size() - 1)];
  const bool relative = d_relativeMovements.value();
  if constexpr (std::is_same_v<DataTypes, Rigid3Types>) {
    const Vec3d translation = (1 - s) * a.linear + s * b.linear;
    const Quat rotation = quatFromEuler(a.angular).slerp(s, quatFromEuler(b.angular));
    Coord x;
    x.center = relative ? Vec3d(m_x0[index].center + translation) : translation;
    x.orientation = relative ? Quat(m_x0[index].orientation * rotation) : rotation;
    x.orientation.normalize();
    return x;
  } else {
    const Coord m = (1 - s) * a + s * b;
    return relative ? Coord(m_x0[index] + m) : m;
  }
}

template <class DataTypes>
void LinearMovementProjectiveConstraint<DataTypes>::projectResponse(VecDeriv& dx) {
  if (!isActive(this->node()->time())) return;
  forEachMoved(dx.size(), [&](std::size_t i) { dx[i] = DataTypes::zeroDeriv(); });
}

template <class DataTypes>
void LinearMovementProjectiveConstraint<DataTypes>::projectPosition(VecCoord& x, double time) {
  if (!isActive(this->node()->time())) return;
  forEachMoved(x.size(), [&](std::size_t i) { x[i] = positionAt(i, time); });
}

template <class DataTypes>
void LinearMovementProjectiveConstraint<DataTypes>::projectVelocity(VecDeriv& v, double time) {
  const double start = this->node()->time();
  if (!isActive(start)) return;
  // Mean velocity over the step [start, time]; when the caller gave the start time itself
  // (no step duration known), over [time, time + dt].
  const double t0 = time > start ? start : time;
  const double t1 = time > start ? time : time + this->node()->dt();
  if (!(t1 > t0)) return;
  forEachMoved(v.size(), [&](std::size_t i) {
    const Coord a = positionAt(i, t0), b = positionAt(i, t1);
    if constexpr (std::is_same_v<DataTypes, Rigid3Types>) {
      v[i].linear = (b.center - a.center) / (t1 - t0);
      v[i].angular = rotationVector(a.orientation, b.orientation) / (t1 - t0);
    } else {
      v[i] = (b - a) / (t1 - t0);
    }
  });
}

template <class DataTypes>
void LinearMovementProjectiveConstraint<DataTypes>::fixedRows(
    std::vector<std::size_t>& rows) const {
  if (!isActive(this->node()->time())) return;
  constexpr std::size_t block = DataTypes::derivSize;
  forEachMoved(this->mstate()->size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < block; ++k) rows.push_back(block * i + k);
  });
}

template class LinearMovementProjectiveConstraint<Vec1Types>;
template class LinearMovementProjectiveConstraint<Vec3Types>;
template class LinearMovementProjectiveConstraint<Rigid3Types>;

}  // namespace stroma
