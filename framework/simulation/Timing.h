// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <string>
#include <string_view>
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
  /// Adds to `phase`; allocates only for a phase it has not seen yet.
  void add(std::string_view phase, double seconds);
  const std::vector<Phase>& phases() const { return m_phases; }
  double seconds(const std::string& phase) const;
  void clear() { m_phases.clear(); }

 private:
  std::vector<Phase> m_phases;
};

/// Adds the time between its construction and destruction to a phase.
class ScopedPhase {
 public:
  /// `phase` must outlive the ScopedPhase (phases are named by string literals): nothing is
  /// copied, so that timing a step allocates nothing.
  ScopedPhase(Timing& timing, std::string_view phase)
      : m_timing(timing), m_phase(phase), m_start(std::chrono::steady_clock::now()) {}
  ~ScopedPhase() {
    m_timing.add(m_phase, std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start)
                              .count());
  }
  ScopedPhase(const ScopedPhase&) = delete;
  ScopedPhase& operator=(const ScopedPhase&) = delete;

 private:
  Timing& m_timing;
  std::string_view m_phase;
  std::chrono::steady_clock::time_point m_start;
};

}  // namespace stroma
