// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Base.h"
#include "core/Types.h"

namespace stroma::test {

/// A DataEngine: `output` is twice `input`, recomputed lazily when read after `input` changed.
class TestEngine final : public Base, public DataEngine {
 public:
  Data<std::vector<double>> d_input{this, "input", {}, "Values to double (n)."};
  Data<std::vector<double>> d_output{this, "output", {}, "Twice the input (n).", {.output = true}};
  Data<int> d_updates{
      this, "updates", 0, "How many times the output was computed.", {.output = true}};

  TestEngine();

 protected:
  void doUpdate() override;
};

/// A loader-like engine: `position` holds `count` points spaced by `spacing` along x, for
/// `src="@loader"` tests.
class TestLoader final : public Base, public DataEngine {
 public:
  Data<int> d_count{this, "count", 2, "Number of points made.", {.min = 0.0}};
  Data<double> d_spacing{this, "spacing", 1.0, "Distance between the points.", {.unit = "m"}};
  Data<FileName> d_filename{this, "filename", {}, "A file that must exist (not read)."};
  Data<std::vector<Vec3d>> d_position{
      this, "position", {}, "Points made (count x 3).", {.unit = "m", .output = true}};

  TestLoader();

 protected:
  void doUpdate() override;
};

}  // namespace stroma::test
