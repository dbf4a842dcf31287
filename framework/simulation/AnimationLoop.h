// SPDX-License-Identifier: MIT
#pragma once

#include "core/Base.h"

namespace stroma {

class Node;
class Timing;

/// Advances a whole scene by one time step. A scene has at most one, in its root node; a
/// scene without one uses DefaultAnimationLoop's behaviour.
class AnimationLoop : public Base {
 public:
  /// One step of length dt from the root, recording phase times in `timing`.
  virtual void step(Node& root, double dt, Timing& timing) = 0;
  /// Whether it solves Lagrangian constraints (FreeMotionAnimationLoop): constraint solvers and
  /// constraint responses to contacts need such a loop.
  virtual bool solvesConstraints() const { return false; }
};

/// Something that advances itself during a step, outside the ODE solvers (a scripted motion,
/// a test driver). The animation loop calls it once per step.
class BehaviorModel : public Base {
 public:
  virtual void updatePosition(double dt) = 0;
};

}  // namespace stroma

namespace stroma {

/// The step of a scene without an animation loop component, and of DefaultAnimationLoop:
/// behavior models, collision (when the root holds a collision pipeline), the solvers, then
/// time += dt.
void animateDefault(Node& root, double dt, Timing& timing);

}  // namespace stroma
