// SPDX-License-Identifier: MIT
#include "UnilateralLagrangianConstraint.h"

#include <algorithm>
#include <cmath>

#include "simulation/StateLinks.h"
#include "core/IndexChecks.h"

namespace stroma {

void UnilateralLagrangianConstraint::init() {
  m_state1 = resolveState<Vec3Types>(*this, l_object1, "object1");
  m_state2 = l_object2 ? resolveState<Vec3Types>(*this, l_object2, "object2") : m_state1;
  if (!m_state1 || !m_state2) return;
  const double length = d_normal.value().norm();
  if (!(length > 0) || !std::isfinite(length)) {
    msgError("must be a non-zero direction", "normal");
    return;
  }
  m_frame = contactFrame(d_normal.value() / length);
}

// The points are checked once every component is initialized: they may come from an engine.
void UnilateralLagrangianConstraint::bwdInit() {
  if (!m_state1 || !m_state2) return;
  if (d_firstPoint.value().size() != d_secondPoint.value().size()) {
    msgError("has " + std::to_string(d_firstPoint.value().size()) + " first points and " +
                 std::to_string(d_secondPoint.value().size()) +
                 " second points: give one of each per pair",
             "second_point");
    return;
  }
  reportIndicesOutOfRange(*this, d_firstPoint.value(), m_state1->size(), "first_point");
  reportIndicesOutOfRange(*this, d_secondPoint.value(), m_state2->size(), "second_point");
}

void UnilateralLagrangianConstraint::buildConstraintRows(ConstraintRows& rows, double dt) {
  if (!m_state1 || !m_state2 || !isValid()) return;
  const auto& x1 = m_state1->readCoord(VecId::position());
  const auto& x2 = m_state2->readCoord(VecId::position());
  const auto& v1 = m_state1->readDeriv(VecId::velocity());
  const auto& v2 = m_state2->readDeriv(VecId::velocity());
  const auto& first = d_firstPoint.value();
  const auto& second = d_secondPoint.value();
  // An engine may change the indices during the run: pairs out of range are left out.
  const std::size_t pairs = std::min(first.size(), second.size());
  for (std::size_t k = 0; k < pairs; ++k) {
    if (first[k] >= x1.size() || second[k] >= x2.size()) continue;
    const double gap = m_frame[0].dot(x2[second[k]] - x1[first[k]]) - d_contactDistance.value();
    const Vec3d slip = dt * (v2[second[k]] - v1[first[k]]);
    const std::size_t row = addContactGroup(rows, m_frame, gap, slip, d_mu.value(), m_rowsPerPair);
    for (int r = 0; r < m_rowsPerPair; ++r)
      for (std::size_t c = 0; c < 3; ++c) {
        const double value = m_frame[static_cast<std::size_t>(r)][static_cast<Eigen::Index>(c)];
        rows.add(row + static_cast<std::size_t>(r), m_state2, second[k] * 3 + c, value);
        rows.add(row + static_cast<std::size_t>(r), m_state1, first[k] * 3 + c, -value);
      }
  }
}

void UnilateralLagrangianConstraint::storeMultipliers(std::span<const double> lambda) {
  auto& forces = d_forces.edit();
  const auto per = static_cast<std::size_t>(m_rowsPerPair);
  forces.resize(lambda.size() / per);
  for (std::size_t k = 0; k < forces.size(); ++k) {
    Vec3d f = Vec3d::Zero();
    for (std::size_t r = 0; r < per; ++r) f += lambda[k * per + r] * m_frame[r];
    forces[k] = f;
  }
}

}  // namespace stroma
