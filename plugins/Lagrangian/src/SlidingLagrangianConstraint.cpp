// SPDX-License-Identifier: MIT
#include "SlidingLagrangianConstraint.h"

#include <algorithm>

#include "simulation/StateLinks.h"
#include "core/IndexChecks.h"

namespace stroma {

void SlidingLagrangianConstraint::init() {
  m_state1 = resolveState<Vec3Types>(*this, l_object1, "object1");
  m_state2 = l_object2 ? resolveState<Vec3Types>(*this, l_object2, "object2") : m_state1;
}

// Checked once every component is initialized (the states may be initialized after this one).
void SlidingLagrangianConstraint::bwdInit() {
  if (!m_state1 || !m_state2) return;
  reportIndicesOutOfRange(*this, std::vector<unsigned>{d_slidingPoint.value()}, m_state1->size(),
                          "sliding_point");
  reportIndicesOutOfRange(*this, std::vector<unsigned>{d_axis1.value()}, m_state2->size(), "axis_1");
  reportIndicesOutOfRange(*this, std::vector<unsigned>{d_axis2.value()}, m_state2->size(), "axis_2");
  if (!isValid()) return;
  const auto& x2 = m_state2->readCoord(VecId::position());
  if ((x2[d_axis2.value()] - x2[d_axis1.value()]).norm() == 0)
    msgError("the axis' ends " + std::to_string(d_axis1.value()) + " and " +
                 std::to_string(d_axis2.value()) + " of " + m_state2->path() +
                 " are at the same place: no axis to slide along",
             "axis_2");
}

void SlidingLagrangianConstraint::buildConstraintRows(ConstraintRows& rows, double) {
  if (!m_state1 || !m_state2 || !isValid()) return;
  const unsigned p = d_slidingPoint.value(), a = d_axis1.value(), b = d_axis2.value();
  const Vec3d& P = m_state1->readCoord(VecId::position())[p];
  const Vec3d& A = m_state2->readCoord(VecId::position())[a];
  const Vec3d& B = m_state2->readCoord(VecId::position())[b];
  const double length = (B - A).norm();
  if (!(length > 0)) return;
  const Vec3d dir = (B - A) / length;
  const double t = std::clamp(dir.dot(P - A) / length, 0.0, 1.0);
  const std::array<Vec3d, 3> frame = contactFrame(dir);
  auto addRow = [&](ConstraintKind kind, double violation, const Vec3d& onP, double onA, double onB,
                    const Vec3d& along) {
    const std::size_t row = rows.addGroup(kind, std::span<const double>(&violation, 1));
    for (std::size_t c = 0; c < 3; ++c) {
      const auto e = static_cast<Eigen::Index>(c);
      rows.add(row, m_state1, p * 3 + c, onP[e]);
      if (onA != 0) rows.add(row, m_state2, a * 3 + c, onA * along[e]);
      if (onB != 0) rows.add(row, m_state2, b * 3 + c, onB * along[e]);
    }
  };
  for (int k = 1; k <= 2; ++k) {
    const Vec3d& n = frame[static_cast<std::size_t>(k)];
    addRow(ConstraintKind::bilateral, n.dot(P - A), n, -(1 - t), -t, n);
    m_directions[static_cast<std::size_t>(k - 1)] = n;
  }
  addRow(ConstraintKind::unilateral, dir.dot(P - A), dir, -1.0, 0.0, dir);
  addRow(ConstraintKind::unilateral, dir.dot(B - P), -dir, 0.0, 1.0, dir);
  m_directions[2] = dir;
  m_directions[3] = -dir;
}

void SlidingLagrangianConstraint::storeMultipliers(std::span<const double> lambda) {
  Vec3d f = Vec3d::Zero();
  for (std::size_t r = 0; r < lambda.size() && r < 4; ++r) f += lambda[r] * m_directions[r];
  d_force.setValue(f);
}

}  // namespace stroma
