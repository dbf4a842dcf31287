// SPDX-License-Identifier: MIT
#include "JointLimitLagrangianConstraint.h"

#include <array>

#include "simulation/StateLinks.h"

namespace stroma {

bool checkJointLimits(Base& owner, const std::vector<unsigned>& indices,
                      const std::vector<double>& lower, const std::vector<double>& upper,
                      std::size_t jointCount) {
  const std::size_t n = indices.size();
  if (lower.size() != n || upper.size() != n) {
    owner.msgError("lower and upper need one bound per index (" + std::to_string(n) + "), got " +
                       std::to_string(lower.size()) + " and " + std::to_string(upper.size()),
                   lower.size() != n ? "lower" : "upper");
    return false;
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (indices[k] >= jointCount) {
      owner.msgError("index " + std::to_string(indices[k]) + " is out of range of the " +
                         std::to_string(jointCount) + " joint values",
                     "indices");
      return false;
    }
    if (!(lower[k] <= upper[k])) {
      owner.msgError("the range of joint value " + std::to_string(indices[k]) +
                         " is empty (lower > upper)",
                     "lower");
      return false;
    }
  }
  return true;
}

void JointLimitLagrangianConstraint::init() {
  m_ready = false;
  m_state = resolveState<Vec1Types>(*this, l_mstate, "mstate");
  if (!m_state) return;
  m_ready = checkJointLimits(*this, d_indices.value(), d_lower.value(), d_upper.value(),
                             m_state->size());
  m_sign.assign(d_indices.value().size(), 1.0);
  d_forces.setValue(std::vector<double>(d_indices.value().size(), 0.0));
}

// One row per limited joint, on the bound nearer to the free value: the two rows of one joint
// would make W singular, and a joint cannot reach both bounds in one step.
void JointLimitLagrangianConstraint::buildConstraintRows(ConstraintRows& rows, double) {
  if (!m_ready || !isValid()) return;
  const auto& q = m_state->readCoord(VecId::position());
  const auto& indices = d_indices.value();
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const double value = q[indices[k]][0];
    const double lower = d_lower.value()[k], upper = d_upper.value()[k];
    const bool nearLower = value - lower <= upper - value;
    m_sign[k] = nearLower ? 1.0 : -1.0;
    const std::array<double, 1> gap{nearLower ? value - lower : upper - value};
    const std::size_t row = rows.addGroup(ConstraintKind::unilateral, gap);
    rows.add(row, m_state, indices[k], m_sign[k]);
  }
}

void JointLimitLagrangianConstraint::storeMultipliers(std::span<const double> lambda) {
  auto& forces = d_forces.edit();
  for (std::size_t k = 0; k < forces.size() && k < lambda.size(); ++k)
    forces[k] = lambda[k] == 0 ? 0.0 : m_sign[k] * lambda[k];  // no -0 printed for an idle stop
}

}  // namespace stroma
