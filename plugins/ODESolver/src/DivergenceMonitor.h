// SPDX-License-Identifier: MIT
// Divergence detection at run time, shared by the time integrators. Non-finite positions or
// velocities always stop the run (StepChecks.h: nothing is left to continue from). The other
// signs of a diverging run are reported here, as an error that stops it or as a warning, after
// the solver's `onDivergence` setting:
//  - energy growth without input (EnergyGrowthCheck, dynamic solvers),
//  - a linear solve that stops far from converged (LinearSolveCheck, implicit solvers),
//  - a Newton iteration that stalls (StaticSolver, EulerImplicitSolver with newtonIterations),
//  - for explicit solvers, a time step above the stability bound (StabilityBound.h), refused
//    before anything moves when onDivergence is "stop".
// Members registering Data on the solver, as ExplicitStabilityCheck does: no base class.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "core/Data.h"
#include "core/DataTraits.h"
#include "simulation/Solvers.h"

namespace stroma {

class MechanicalOperations;

enum class OnDivergence { stop, warn };

template <>
struct EnumKeywords<OnDivergence> {
  static constexpr std::array<std::string_view, 2> names{"stop", "warn"};
};

enum class DivergenceKind { energyGrowth, linearSolve, newtonStall, stabilityBound };

/// A solver's `onDivergence` setting and its reports.
class DivergenceMonitor {
 public:
  explicit DivergenceMonitor(OdeSolver& solver) : m_solver(solver) {}

 private:
  OdeSolver& m_solver;  // first: the Data below registers with it
  std::array<long long, 4> m_counts{};

 public:
  Data<OnDivergence> d_onDivergence{
      &m_solver, "onDivergence", OnDivergence::warn,
      "What a divergence found at run time does (kinetic energy growing without input, a linear "
      "solve stopped far from converged, a stalled Newton iteration, and for explicit solvers a "
      "time step above the stability bound): stop = an error naming the step, this solver and "
      "the worst vertex, which ends the run (stroma run exits with code 1); warn = a warning the "
      "first time for each kind, the later ones counted at the end. Non-finite positions or "
      "velocities stop the run in both modes."};

  bool stops() const { return d_onDivergence.value() == OnDivergence::stop; }

  /// Reports a divergence of `kind` at the solver's `step` (time: the end of the step):
  /// `reason` says what was seen, `worst` the worst vertex, `field` the setting behind the
  /// criterion. Returns false when the run stops (the error is logged).
  bool report(MechanicalOperations& mop, DivergenceKind kind, long long step,
              const std::string& reason, const std::string& worst, const std::string& field);

  /// At the solver's cleanup: the counts of the warnings given once.
  void summarize(long long steps) const;
};

/// Energy growth without input, on the kinetic energy T = 1/2 v.M v (a cheap proxy: the
/// potential energies cost a pass over the elements, and not every force field has one). Two
/// criteria, both with the factor `energyGrowth`:
///  - a blow-up: the sum of T over two consecutive steps grew by the factor at each of three
///    steps in a row (found within five steps of a start, as an explicit solver far above its
///    bound shows it; the sum of two steps, because an unstable oscillating mode moves its
///    energy between positions and velocities from one step to the next). A load, an impact or
///    an imposed motion of finite power makes T grow at most like a power of time t^p from its
///    start, or jump once: from a start at rest the sums grow by 2^p + 1, (3^p + 2^p) / (2^p +
///    1), ..., which pass 10 three times in a row only for p of 8 or more. Velocities at
///    round-off level (the fastest dof moving less than 1e-9 of the largest coordinate per
///    step) are not counted, so that noise at rest is never taken for a blow-up.
///  - a slower divergence: the largest T of each window of `energyWindow` steps grew by the
///    factor from each window to the next, three times in a row (four windows). An unstable
///    linear(ized) scheme multiplies T by a constant factor per step: it is found within three
///    windows once that factor is at least energyGrowth^(1 / energyWindow); with the defaults,
///    t^p passes three times in a row only for p above about 6 (the ratios of the window
///    maxima are at most 2^p, 1.5^p and (4/3)^p after the first).
/// Either way the state grew by orders of magnitude: with onDivergence="warn" the run goes on
/// but ends as a failure. Limits: slower exponential growth is not seen (the run then ends in
/// non-finite values, always stopped); a divergence in the positions only (StaticSolver, where
/// v = 0) is not seen here.
class EnergyGrowthCheck {
 public:
  explicit EnergyGrowthCheck(OdeSolver& solver) : m_solver(solver) {}

 private:
  OdeSolver& m_solver;
  double m_lastEnergy = 0;           // T after the previous step
  double m_lastPair = 0;             // T of the previous two steps, summed
  std::array<double, 4> m_recent{};  // those sums over the current streak, oldest first
  int m_streak = 0;                  // consecutive steps whose sum grew by energyGrowth
  double m_windowMax = 0;
  int m_inWindow = 0;
  std::array<double, 4> m_maxima{};  // the last four window maxima, oldest first
  int m_windows = 0;

 public:
  Data<double> d_energyGrowth{&m_solver,
                              "energyGrowth",
                              10.0,
                              "Factor by which the kinetic energy must grow at each of three "
                              "steps in a row (a blow-up), or its largest value over a window of "
                              "energyWindow steps over the previous window three windows in a "
                              "row, to count as a divergence (0: not checked).",
                              {.min = 0.0}};
  Data<int> d_energyWindow{&m_solver,
                           "energyWindow",
                           10,
                           "Steps per window of the energy-growth check.",
                           {.min = 1.0, .max = 1e6}};

  /// After a step (finite state): feeds T to the step and window criteria and returns true
  /// when one shows a divergence, with what was seen in `reason`.
  bool grew(MechanicalOperations& mop, std::string& reason);

 private:
  bool blewUp(MechanicalOperations& mop, double energy, double growth, std::string& reason);
};

/// A linear solve that ends unconverged counts as a divergence when its relative residual
/// stays above `maxLinearResidual` (or is not finite): an iterative solver capped far from the
/// solution, or one whose residual grew (an indefinite matrix). One just short of its tolerance
/// is only the linear solver's own warning.
class LinearSolveCheck {
 public:
  explicit LinearSolveCheck(OdeSolver& solver) : m_solver(solver) {}

 private:
  OdeSolver& m_solver;

 public:
  Data<double> d_maxLinearResidual{&m_solver,
                                   "maxLinearResidual",
                                   0.1,
                                   "Relative residual ||r|| / ||b|| above which a linear solve "
                                   "that stopped unconverged counts as a divergence (0.1: not "
                                   "even one decade of reduction; interactive scenes cap CG a "
                                   "percent or so from the solution on purpose).",
                                   {.min = 0.0}};

  /// Whether `r` counts as a divergence; `reason` then says why, naming `linearSolver`.
  bool diverged(const LinearSolveReport& r, const Base& linearSolver, std::string& reason) const;
};

}  // namespace stroma
