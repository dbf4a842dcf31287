// SPDX-License-Identifier: MIT
#include "simulation/Timing.h"

namespace stroma {

void Timing::add(std::string_view phase, double seconds) {
  for (auto& p : m_phases) {
    if (p.name == phase) {
      p.seconds += seconds;
      ++p.calls;
      return;
    }
  }
  m_phases.push_back({std::string(phase), seconds, 1});
}

double Timing::seconds(const std::string& phase) const {
  for (const auto& p : m_phases)
    if (p.name == phase) return p.seconds;
  return 0;
}

}  // namespace stroma
