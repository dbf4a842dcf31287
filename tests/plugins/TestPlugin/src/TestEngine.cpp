// SPDX-License-Identifier: MIT
#include "TestEngine.h"

namespace stroma::test {

TestEngine::TestEngine() {
  addInput(&d_input);
  addOutput(&d_output);
}

void TestEngine::doUpdate() {
  d_updates.setValue(d_updates.value() + 1);
  std::vector<double> doubled = d_input.value();
  for (double& x : doubled) x *= 2;
  d_output.setValue(std::move(doubled));
}

TestLoader::TestLoader() {
  addInput(&d_count);
  addInput(&d_spacing);
  addOutput(&d_position);
}

void TestLoader::doUpdate() {
  std::vector<Vec3d> points;
  for (int i = 0; i < d_count.value(); ++i) points.emplace_back(i * d_spacing.value(), 0, 0);
  d_position.setValue(std::move(points));
}

}  // namespace stroma::test
