// SPDX-License-Identifier: MIT
// What the constraint solvers share: they only act under FreeMotionAnimationLoop, and they
// report the solves that stop unconverged the same way.
#pragma once

#include <string>

#include "core/Message.h"
#include "core/Node.h"
#include "simulation/AnimationLoop.h"
#include "simulation/Constraints.h"

namespace stroma::lagrangian {

/// Reports an error on `solver` (bad input) and returns false when the root has no
/// FreeMotionAnimationLoop: nothing would ask it to solve.
inline bool checkFreeMotionLoop(Base& solver) {
  const Node* node = solver.node();
  if (!node) return true;
  const AnimationLoop* loop = node->root().get<AnimationLoop>();
  if (loop && loop->solvesConstraints()) return true;
  solver.msgError("solves Lagrangian constraints, which only FreeMotionAnimationLoop asks for: add "
                  "<FreeMotionAnimationLoop/> to the root node" +
                  std::string(loop ? " instead of its " + loop->className() : ""));
  return false;
}

/// A solver's count of its solves and of those that stopped unconverged.
struct SolveCounts {
  long long solves = 0;
  long long unconverged = 0;
};

/// Counts a solve; warns (on `field`, the iteration limit) the first time one stops
/// unconverged, later ones being counted for unconvergedSummary.
inline void countSolve(Base& solver, const ConstraintSolveReport& report, double tolerance,
                       const char* field, SolveCounts& counts) {
  ++counts.solves;
  if (!report.converged && counts.unconverged++ == 0)
    solver.msgWarning("stopped after " + std::to_string(report.iterations) +
                          " iterations without converging: error " + formatNumber(report.error) +
                          " > tolerance " + formatNumber(tolerance) + " (raise " + field +
                          " or the tolerance); later ones are counted",
                      field);
}

/// At cleanup: how many solves stopped unconverged, when more than the first (already told).
inline void unconvergedSummary(Base& solver, const SolveCounts& counts, const char* field) {
  if (counts.unconverged > 1)
    solver.msgWarning("stopped unconverged in " + std::to_string(counts.unconverged) + " of " +
                          std::to_string(counts.solves) + " solves",
                      field);
}

}  // namespace stroma::lagrangian
