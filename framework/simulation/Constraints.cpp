// SPDX-License-Identifier: MIT
#include "simulation/Constraints.h"

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

}  // namespace stroma
