// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace stroma {

/// Wall time spent per named phase of a run ("load", "init", "step", "computeForce", ...),
/// accumulated over steps, in the order the phases first appeared. One per scene.
class Timing {
 public:
  struct Phase {
    std::string name;
    double seconds = 0;
    long long calls = 0;
  };
  void add(const std::string& phase, double seconds);
  const std::vector<Phase>& phases() const { return m_phases; }
  double seconds(const std::string& phase) const;
  void clear() { m_phases.clear(); }

 private:
  std::vector<Phase> m_phases;
};

/// Adds the time between its construction and destruction to a phase.
class ScopedPhase {
 public:
  ScopedPhase(Timing& timing, std::string phase)
      : m_timing(timing), m_phase(std::move(phase)), m_start(std::chrono::steady_clock::now()) {}
  ~ScopedPhase() {
    m_timing.add(m_phase, std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start)
                              .count());
  }
  ScopedPhase(const ScopedPhase&) = delete;
  ScopedPhase& operator=(const ScopedPhase&) = delete;

 private:
  Timing& m_timing;
  std::string m_phase;
  std::chrono::steady_clock::time_point m_start;
};

}  // namespace stroma
