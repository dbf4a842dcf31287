// SPDX-License-Identifier: MIT
#pragma once

#include "core/Base.h"

namespace stroma::test {

/// Checks its input in init(), as components do for what the Data options cannot express:
/// `stiffness` must be positive (the Data itself accepts any finite number).
class TestInitCheck final : public Base {
 public:
  Data<double> d_stiffness{
      this, "stiffness", 1.0, "Must be positive (checked in init()).", {.unit = "N/m"}};

  void init() override;
};

}  // namespace stroma::test
