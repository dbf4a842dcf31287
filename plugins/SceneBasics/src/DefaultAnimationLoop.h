// SPDX-License-Identifier: MIT
#pragma once

#include "simulation/AnimationLoop.h"

namespace stroma {

/// The standard step of a scene (see animateDefault). SOFA's options are accepted.
class DefaultAnimationLoop final : public AnimationLoop {
 public:
  Data<bool> d_parallelODESolving{this, "parallelODESolving", false,
                                  "Solve independent solver nodes in parallel (accepted; "
                                  "solver nodes run in scene order)."};
  Data<bool> d_computeBoundingBox{this, "computeBoundingBox", false,
                                  "Recompute the scene bounding box each step (viewers only)."};

  void step(Node& root, double dt, Timing& timing) override;
};

}  // namespace stroma
