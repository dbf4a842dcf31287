// SPDX-License-Identifier: MIT
#include "JointLimitConstraint.h"

#include "JointLimitLagrangianConstraint.h"

#include <algorithm>

namespace stroma {

void JointLimitConstraint::init() {
  ProjectiveConstraint<Vec1Types>::init();
  m_ready = false;
  if (!mstate()) return;
  m_ready = checkJointLimits(*this, d_indices.value(), d_lower.value(), d_upper.value(),
                             mstate()->size());
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
