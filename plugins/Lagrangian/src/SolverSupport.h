// SPDX-License-Identifier: MIT
// What the constraint solvers share: they only act under FreeMotionAnimationLoop.
#pragma once

#include "core/Node.h"
#include "simulation/AnimationLoop.h"

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

}  // namespace stroma::lagrangian
