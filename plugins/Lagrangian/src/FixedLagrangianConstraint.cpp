// SPDX-License-Identifier: MIT
#include "FixedLagrangianConstraint.h"

#include <array>
#include <numeric>

#include "simulation/StateLinks.h"
#include "core/IndexChecks.h"

namespace stroma {

namespace {

// The rotation vector (world axes) of the turn from a to b, in (-pi, pi].
Vec3d rotationVector(const Quat& a, const Quat& b) {
  const Eigen::AngleAxisd turn((b * a.inverse()).normalized());
  double angle = turn.angle();
  if (angle > M_PI) angle -= 2 * M_PI;
  return angle * turn.axis();
}

}  // namespace

template <class DataTypes>
void FixedLagrangianConstraint<DataTypes>::init() {
  m_state = resolveState<DataTypes>(*this, l_mstate, "mstate");
}

// The indices and start positions are taken once every component is initialized: they may come
// from an engine (a BoxROI) over a state initialized after this component.
template <class DataTypes>
void FixedLagrangianConstraint<DataTypes>::bwdInit() {
  if (!m_state) return;
  if (d_fixAll.value()) {
    m_held.resize(m_state->size());
    std::iota(m_held.begin(), m_held.end(), 0u);
  } else {
    m_held = d_indices.value();
    if (!reportIndicesOutOfRange(*this, m_held, m_state->size(), "indices")) return;
    if (m_held.empty())
      msgWarning("holds nothing: give indices, or fixAll=\"1\"", "indices");
  }
  const auto& x = m_state->readCoord(VecId::position());
  m_start.clear();
  for (unsigned i : m_held) m_start.push_back(x[i]);
}

template <class DataTypes>
void FixedLagrangianConstraint<DataTypes>::buildConstraintRows(ConstraintRows& rows, double) {
  if (!m_state || !isValid()) return;
  const auto& x = m_state->readCoord(VecId::position());
  constexpr std::size_t dim = DataTypes::derivSize;
  for (std::size_t k = 0; k < m_held.size(); ++k) {
    const std::size_t i = m_held[k];
    Vec3d delta;
    if constexpr (kRigid) delta = x[i].center - m_start[k].center;
    else delta = x[i] - m_start[k];
    for (std::size_t c = 0; c < 3; ++c) {
      const std::array<double, 1> violation{delta[static_cast<Eigen::Index>(c)]};
      rows.add(rows.addGroup(ConstraintKind::bilateral, violation), m_state, i * dim + c, 1.0);
    }
    if constexpr (kRigid) {
      const Vec3d theta = rotationVector(m_start[k].orientation, x[i].orientation);
      for (std::size_t c = 0; c < 3; ++c) {
        const std::array<double, 1> violation{theta[static_cast<Eigen::Index>(c)]};
        rows.add(rows.addGroup(ConstraintKind::bilateral, violation), m_state, i * dim + 3 + c,
                 1.0);
      }
    }
  }
}

template <class DataTypes>
void FixedLagrangianConstraint<DataTypes>::storeMultipliers(std::span<const double> lambda) {
  // The multipliers act on the held points along +delta: the holding force is lambda itself.
  auto& forces = d_forces.edit();
  forces.resize(lambda.size() / 3);
  for (std::size_t k = 0; k < forces.size(); ++k)
    forces[k] = Vec3d(lambda[3 * k], lambda[3 * k + 1], lambda[3 * k + 2]);
}

template class FixedLagrangianConstraint<Vec3Types>;
template class FixedLagrangianConstraint<Rigid3Types>;

}  // namespace stroma
