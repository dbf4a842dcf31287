// SPDX-License-Identifier: MIT
#include "simulation/Constraints.h"

#include <algorithm>
#include <cmath>

namespace stroma {

std::size_t ConstraintRows::addGroup(ConstraintKind kind, std::span<const double> violations,
                                     double mu) {
  const std::size_t first = m_violations.size();
  m_groups.push_back({kind, first, static_cast<int>(violations.size()), mu});
  m_violations.insert(m_violations.end(), violations.begin(), violations.end());
  return first;
}

void ConstraintRows::add(std::size_t row, const BaseMechanicalState* state, std::size_t dof,
                         double value) {
  std::size_t s = 0;
  while (s < m_usedStates && m_states[s] != state) ++s;
  if (s == m_usedStates) {
    // A new state this step: reuse a slot (and its entry storage) when there is one.
    if (m_usedStates == m_states.size()) {
      m_states.push_back(state);
      m_entries.emplace_back();
    } else {
      m_states[m_usedStates] = state;
      m_entries[m_usedStates].clear();
    }
    ++m_usedStates;
  }
  m_entries[s].push_back({row, dof, value});
}

void ConstraintRows::clear() {
  m_groups.clear();
  m_violations.clear();
  for (std::size_t s = 0; s < m_usedStates; ++s) m_entries[s].clear();
  m_usedStates = 0;
}

std::array<Vec3d, 3> contactFrame(const Vec3d& n) {
  // The axis least aligned with n gives a well-conditioned first tangent.
  const Vec3d helper = std::abs(n.x()) < 0.6 ? Vec3d::UnitX() : Vec3d::UnitY();
  const Vec3d t1 = n.cross(helper).normalized();
  return {n, t1, n.cross(t1)};
}

std::size_t addContactGroup(ConstraintRows& rows, const std::array<Vec3d, 3>& frame, double gap,
                            const Vec3d& slip, double mu, int& rowCount) {
  if (!(mu > 0)) {
    rowCount = 1;
    return rows.addGroup(ConstraintKind::unilateral, std::span<const double>(&gap, 1));
  }
  rowCount = 3;
  const std::array<double, 3> violations{gap, frame[1].dot(slip), frame[2].dot(slip)};
  return rows.addGroup(ConstraintKind::friction, violations, mu);
}

ConstraintLawResiduals lawResiduals(const ConstraintProblem& problem, double coneSlack) {
  ConstraintLawResiduals r;
  const Eigen::VectorXd delta = problem.violation + problem.W * problem.lambda;
  const Eigen::VectorXd& lambda = problem.lambda;
  for (const ConstraintGroup& g : problem.groups) {
    const auto i = static_cast<Eigen::Index>(g.firstRow);
    switch (g.kind) {
      case ConstraintKind::bilateral:
        for (int k = 0; k < g.rowCount; ++k) r.bilateral = std::max(r.bilateral, std::abs(delta[i + k]));
        break;
      case ConstraintKind::unilateral:
      case ConstraintKind::friction:
        r.negativeForce = std::max(r.negativeForce, -lambda[i]);
        r.penetration = std::max(r.penetration, -delta[i]);
        r.complementarity = std::max(r.complementarity, std::abs(lambda[i] * delta[i]));
        if (g.kind == ConstraintKind::friction) {
          const double tangent = Eigen::Vector2d(lambda[i + 1], lambda[i + 2]).norm();
          const double limit = g.mu * std::max(0.0, lambda[i]);
          r.outsideCone = std::max(r.outsideCone, tangent - limit);
          if (tangent < limit * (1 - coneSlack))
            r.slipWhileInside = std::max(r.slipWhileInside,
                                         Eigen::Vector2d(delta[i + 1], delta[i + 2]).norm());
        }
        break;
    }
  }
  return r;
}

}  // namespace stroma
