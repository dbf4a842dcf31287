// SPDX-License-Identifier: MIT
#pragma once

#include "core/Base.h"

namespace stroma {

/// Sets the gravity of its node (SOFA's Gravity, a context object): at init the node's
/// `gravity` takes this value, and the nodes below inherit it as they inherit a gravity written
/// on the node itself (Node::gravity(): the nearest node up that sets one). A node below that
/// sets its own gravity keeps it. Masses read the gravity at every step, so the value applies
/// whatever the order of the components in the node; reinit() applies a changed value.
class Gravity final : public Base {
 public:
  Data<Vec3d> d_gravity{this, "gravity", Vec3d(0, 0, 0),
                        "Gravity acceleration of the node and the nodes below.",
                        {.unit = "m/s^2"}};

  void init() override;
  void reinit() override { init(); }
};

}  // namespace stroma
