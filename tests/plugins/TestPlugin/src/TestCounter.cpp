// SPDX-License-Identifier: MIT
#include "TestCounter.h"

namespace stroma::test {

void TestCounter::updatePosition(double dt) {
  const int step = d_count.value() + 1;
  d_count.setValue(step);
  d_total.setValue(d_total.value() + d_increment.value());
  d_elapsed.setValue(d_elapsed.value() + dt);
  if (d_failAtStep.value() == step)
    msgError("failing at step " + std::to_string(step) + " as failAtStep asks", "failAtStep");
}

}  // namespace stroma::test
