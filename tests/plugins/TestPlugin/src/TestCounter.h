// SPDX-License-Identifier: MIT
#pragma once

#include "core/BaseState.h"
#include "core/Link.h"
#include "simulation/AnimationLoop.h"

namespace stroma::test {

/// Counts its steps: each updatePosition adds one to `count` and `increment` to `total`.
/// With failAtStep=N it reports an error at its N-th step, as a diverging simulation would.
class TestCounter final : public BehaviorModel {
 public:
  Data<int> d_count{
      this, "count", 0, "Number of steps taken (updatePosition calls).", {.output = true}};
  Data<double> d_increment{
      this, "increment", 1.0, "Added to 'total' at each step.", {.min = 0.0, .max = 10.0}};
  Data<double> d_total{this, "total", 0.0, "Sum of the increments so far.", {.output = true}};
  Data<double> d_elapsed{
      this, "elapsed", 0.0, "Sum of the time steps received.", {.unit = "s", .output = true}};
  Data<int> d_failAtStep{this,
                         "failAtStep",
                         0,
                         "Report an error at this step (1 for the first); 0 never fails.",
                         {.min = 0.0}};
  Link<BaseState> l_mstate{this, "mstate", "A mechanical state (optional, unused)."};

  void updatePosition(double dt) override;
};

}  // namespace stroma::test
