// SPDX-License-Identifier: MIT
#include "Gravity.h"

#include <cmath>

#include "core/Node.h"

namespace stroma {

void Gravity::init() {
  const Vec3d g = d_gravity.value();
  if (!g.allFinite()) {
    msgError("gravity must be three finite numbers, got " + d_gravity.valueText(), "gravity");
    return;
  }
  if (!node()) {
    msgError("is not in a node: there is no context to set the gravity of");
    return;
  }
  node()->d_gravity.setValue(g);
}

}  // namespace stroma
