// SPDX-License-Identifier: MIT
#include "DefaultAnimationLoop.h"

namespace stroma {

void DefaultAnimationLoop::step(Node& root, double dt, Timing& timing) {
  animateDefault(root, dt, timing);
}

}  // namespace stroma
