// SPDX-License-Identifier: MIT
#include "TestInitCheck.h"

#include <string>

namespace stroma::test {

void TestInitCheck::init() {
  if (d_stiffness.value() <= 0)
    msgError("expected a positive stiffness, got " + d_stiffness.valueText(), "stiffness");
}

}  // namespace stroma::test
