// SPDX-License-Identifier: MIT
#include "DivergenceMonitor.h"

#include <algorithm>
#include <cmath>

#include "core/Message.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

namespace {

const char* kindName(DivergenceKind kind) {
  switch (kind) {
    case DivergenceKind::energyGrowth:
      return "energy growth";
    case DivergenceKind::linearSolve:
      return "unconverged linear solve";
    case DivergenceKind::newtonStall:
      return "stalled Newton iteration";
    case DivergenceKind::stabilityBound:
      return "time step above the stability bound";
  }
  return "divergence";
}

}  // namespace

bool DivergenceMonitor::report(MechanicalOperations& mop, DivergenceKind kind, long long step,
                               const std::string& reason, const std::string& worst,
                               const std::string& field) {
  const std::string text = "divergence (" + std::string(kindName(kind)) + ") at step " +
                           std::to_string(step) + ", time " + formatNumber(mop.endTime()) +
                           " s: " + reason + "; worst vertex: " + worst;
  if (stops()) {
    m_solver.msgError(text + ". The run stops (onDivergence=\"stop\"; \"warn\" would go on)",
                      field);
    return false;
  }
  if (m_counts[static_cast<std::size_t>(kind)]++ > 0) return true;
  const std::string goesOn = ". The run goes on (onDivergence=\"warn\"; \"stop\" would end it)";
  if (kind == DivergenceKind::energyGrowth)
    // The state grew by orders of magnitude: whatever follows is not a result.
    m_solver.msgRunFailure(text + goesOn +
                               " but ends as a failure: its state is no longer "
                               "meaningful; later ones are counted",
                           field);
  else
    m_solver.msgWarning(text + goesOn + "; later ones are counted", field);
  return true;
}

void DivergenceMonitor::summarize(long long steps) const {
  for (std::size_t k = 0; k < m_counts.size(); ++k)
    if (m_counts[k] > 1)
      m_solver.msgWarning(std::string(kindName(static_cast<DivergenceKind>(k))) + " seen in " +
                              std::to_string(m_counts[k]) + " of " + std::to_string(steps) +
                              " steps",
                          "onDivergence");
}

bool EnergyGrowthCheck::blewUp(MechanicalOperations& mop, double energy, double growth,
                               std::string& reason) {
  // The sum of two consecutive steps' T: an unstable oscillating mode moves its energy between
  // positions and velocities from step to step, which makes T alone jump up and down.
  const double pair = energy + m_lastEnergy;
  m_lastEnergy = energy;
  const bool grewThisStep = m_lastPair > 0 && pair >= growth * m_lastPair;
  m_lastPair = pair;
  if (!grewThisStep) {
    m_streak = 0;
    m_recent[0] = pair;  // the streak's first value, should the next step grow
    return false;
  }
  if (m_streak < 3) {
    m_recent[static_cast<std::size_t>(++m_streak)] = pair;
  } else {
    std::rotate(m_recent.begin(), m_recent.begin() + 1, m_recent.end());
    m_recent.back() = pair;
  }
  if (m_streak < 3) return false;
  // Above round-off: the fastest dof moves by more than 1e-9 of the largest coordinate.
  const double dt = mop.endTime() - mop.time();
  const double speed = mop.worstVertex(VecId::velocity()).value;
  const double scale = mop.worstVertex(VecId::position()).value;
  if (!(speed * dt > 1e-9 * scale)) return false;
  reason = "the kinetic energy of two consecutive steps grew by a factor of " +
           formatNumber(growth) + " or more at each of the last three steps (" +
           formatNumber(m_recent[0]) + ", " + formatNumber(m_recent[1]) + ", " +
           formatNumber(m_recent[2]) + ", " + formatNumber(m_recent[3]) +
           " J): the state is blowing up, an unstable scheme (lower dt, or use an implicit "
           "solver)";
  m_streak = 0;  // the next report needs three new growing steps, from this one
  m_recent[0] = pair;
  return true;
}

bool EnergyGrowthCheck::grew(MechanicalOperations& mop, std::string& reason) {
  const double growth = d_energyGrowth.value();
  if (!(growth > 0)) return false;
  const double energy = mop.kineticEnergy();
  if (blewUp(mop, energy, growth, reason)) return true;
  m_windowMax = std::max(m_windowMax, energy);
  if (++m_inWindow < d_energyWindow.value()) return false;
  // A window is complete: shift it into the last four maxima.
  for (std::size_t i = 0; i + 1 < m_maxima.size(); ++i) m_maxima[i] = m_maxima[i + 1];
  m_maxima.back() = m_windowMax;
  m_windowMax = 0;
  m_inWindow = 0;
  if (++m_windows < static_cast<int>(m_maxima.size())) return false;
  // Three growths by the factor in a row, from a window that moved at all.
  if (!(m_maxima[0] > 0)) return false;
  for (std::size_t i = 0; i + 1 < m_maxima.size(); ++i)
    if (!(m_maxima[i + 1] >= growth * m_maxima[i])) return false;
  reason = "the largest kinetic energy of each window of " +
           std::to_string(d_energyWindow.value()) + " steps grew by a factor of " +
           formatNumber(growth) + " or more three windows in a row (" + formatNumber(m_maxima[0]) +
           ", " + formatNumber(m_maxima[1]) + ", " + formatNumber(m_maxima[2]) + ", " +
           formatNumber(m_maxima[3]) +
           " J), faster than any load or imposed motion of finite power: an unstable scheme " +
           "(lower dt, or use an implicit solver)";
  m_windows = 0;  // the next report needs four new windows
  return true;
}

bool LinearSolveCheck::diverged(const LinearSolveReport& r, const Base& linearSolver,
                                std::string& reason) const {
  const double limit = d_maxLinearResidual.value();
  if (r.converged || (std::isfinite(r.residual) && r.residual <= limit)) return false;
  reason = "the linear solver " + linearSolver.path() + " stopped after " +
           std::to_string(r.iterations) + " iterations with relative residual " +
           formatNumber(r.residual) + " > maxLinearResidual " + formatNumber(limit) +
           (r.residual > 1 ? " (the residual grew: is the matrix positive definite?)"
                            : " (raise its iterations, precondition it, or use a direct solver)");
  return true;
}

}  // namespace stroma
