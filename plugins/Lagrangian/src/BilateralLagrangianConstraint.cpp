// SPDX-License-Identifier: MIT
#include "BilateralLagrangianConstraint.h"

#include <algorithm>
#include <array>

#include "simulation/StateLinks.h"
#include "core/IndexChecks.h"

namespace stroma {

template <class DataTypes>
void BilateralLagrangianConstraint<DataTypes>::init() {
  m_state1 = resolveState<DataTypes>(*this, l_object1, "object1");
  m_state2 = l_object2 ? resolveState<DataTypes>(*this, l_object2, "object2") : m_state1;
}

// The points are checked once every component is initialized: they may come from an engine
// (a BoxROI's indices) over a state that its own node initializes after this one.
template <class DataTypes>
void BilateralLagrangianConstraint<DataTypes>::bwdInit() {
  if (!m_state1 || !m_state2) return;
  const auto& first = d_firstPoint.value();
  const auto& second = d_secondPoint.value();
  if (first.size() != second.size()) {
    msgError("has " + std::to_string(first.size()) + " first points and " +
                 std::to_string(second.size()) + " second points: give one of each per pair",
             "second_point");
    return;
  }
  reportIndicesOutOfRange(*this, first, m_state1->size(), "first_point");
  reportIndicesOutOfRange(*this, second, m_state2->size(), "second_point");
  if constexpr (kRigid) {
    m_orientationOffsets.assign(first.size(), Quat::Identity());
    if (d_keepOrientationDifference.value() && isValid()) {
      const auto& x1 = m_state1->readCoord(VecId::position());
      const auto& x2 = m_state2->readCoord(VecId::position());
      for (std::size_t k = 0; k < first.size(); ++k)
        m_orientationOffsets[k] = x2[second[k]].orientation * x1[first[k]].orientation.inverse();
    }
  }
}

template <class DataTypes>
void BilateralLagrangianConstraint<DataTypes>::buildConstraintRows(ConstraintRows& rows, double) {
  if (!d_activate.value() || !m_state1 || !m_state2 || !isValid()) return;
  const auto& first = d_firstPoint.value();
  const auto& second = d_secondPoint.value();
  const auto& x1 = m_state1->readCoord(VecId::position());
  const auto& x2 = m_state2->readCoord(VecId::position());
  constexpr std::size_t dim = DataTypes::derivSize;
  // An engine may change the indices during the run: pairs out of range are left out.
  const std::size_t pairs = std::min(first.size(), second.size());
  for (std::size_t k = 0; k < pairs; ++k) {
    if (first[k] >= x1.size() || second[k] >= x2.size()) continue;
    Vec3d delta;
    if constexpr (kRigid) delta = x2[second[k]].center - x1[first[k]].center;
    else delta = x2[second[k]] - x1[first[k]];
    for (int c = 0; c < 3; ++c) {
      const std::array<double, 1> violation{delta[c]};
      const std::size_t row = rows.addGroup(ConstraintKind::bilateral, violation);
      rows.add(row, m_state2, second[k] * dim + static_cast<std::size_t>(c), 1.0);
      rows.add(row, m_state1, first[k] * dim + static_cast<std::size_t>(c), -1.0);
    }
    if constexpr (kRigid) {
      // The rotation vector taking q1 (times the kept offset) to q2, in the world frame.
      const Quat offset =
          k < m_orientationOffsets.size() ? m_orientationOffsets[k] : Quat::Identity();
      const Quat q = x2[second[k]].orientation * (offset * x1[first[k]].orientation).inverse();
      const Eigen::AngleAxisd rotation(q.normalized());
      double angle = rotation.angle();
      if (angle > M_PI) angle -= 2 * M_PI;
      const Vec3d theta = angle * rotation.axis();
      for (int c = 0; c < 3; ++c) {
        const std::array<double, 1> violation{theta[c]};
        const std::size_t row = rows.addGroup(ConstraintKind::bilateral, violation);
        rows.add(row, m_state2, second[k] * dim + 3 + static_cast<std::size_t>(c), 1.0);
        rows.add(row, m_state1, first[k] * dim + 3 + static_cast<std::size_t>(c), -1.0);
      }
    }
  }
}

template <class DataTypes>
void BilateralLagrangianConstraint<DataTypes>::storeMultipliers(std::span<const double> lambda) {
  auto& forces = d_forces.edit();
  const std::size_t perPair = kRigid ? 6 : 3;
  forces.resize(lambda.size() / 3);
  for (std::size_t k = 0; k * perPair < lambda.size(); ++k)
    for (std::size_t part = 0; part < perPair / 3; ++part)
      forces[k * (perPair / 3) + part] =
          Vec3d(lambda[k * perPair + 3 * part], lambda[k * perPair + 3 * part + 1],
                lambda[k * perPair + 3 * part + 2]);
}

template class BilateralLagrangianConstraint<Vec3Types>;
template class BilateralLagrangianConstraint<Rigid3Types>;

}  // namespace stroma
