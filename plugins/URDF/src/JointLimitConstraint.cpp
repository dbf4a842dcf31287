// SPDX-License-Identifier: MIT
#include "JointLimitConstraint.h"

#include <algorithm>

namespace stroma {

void JointLimitConstraint::init() {
  ProjectiveConstraint<Vec1Types>::init();
  m_ready = false;
  if (!mstate()) return;
  const std::size_t n = d_indices.value().size();
  if (d_lower.value().size() != n || d_upper.value().size() != n) {
    msgError("lower and upper need one bound per index (" + std::to_string(n) + "), got " +
                 std::to_string(d_lower.value().size()) + " and " +
                 std::to_string(d_upper.value().size()),
             d_lower.value().size() != n ? "lower" : "upper");
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (d_indices.value()[k] >= mstate()->size()) {
      msgError("index " + std::to_string(d_indices.value()[k]) + " is out of range of the " +
                   std::to_string(mstate()->size()) + " joint values",
               "indices");
      return;
    }
    if (!(d_lower.value()[k] <= d_upper.value()[k])) {
      msgError("the range of joint value " + std::to_string(d_indices.value()[k]) +
                   " is empty (lower > upper)",
               "lower");
      return;
    }
  }
  m_ready = true;
}

void JointLimitConstraint::projectPosition(VecCoord& x, double) {
  if (!m_ready) return;
  for (std::size_t k = 0; k < d_indices.value().size(); ++k) {
    double& q = x[d_indices.value()[k]][0];
    q = std::clamp(q, d_lower.value()[k], d_upper.value()[k]);
  }
}

void JointLimitConstraint::projectVelocity(VecDeriv& v, double) {
  if (!m_ready) return;
  const VecCoord& x = mstate()->readCoord(VecId::position());
  for (std::size_t k = 0; k < d_indices.value().size(); ++k) {
    const unsigned j = d_indices.value()[k];
    double& qdot = v[j][0];
    if (x[j][0] <= d_lower.value()[k] && qdot < 0) qdot = 0;
    if (x[j][0] >= d_upper.value()[k] && qdot > 0) qdot = 0;
  }
}

}  // namespace stroma
