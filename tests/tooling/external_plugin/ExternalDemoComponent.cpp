// SPDX-License-Identifier: MIT
#include "ExternalDemoComponent.h"

#include <string>

namespace externaldemo {

void ExternalDemoComponent::init() {
  msgInfo("external component initialized with stiffness " + std::to_string(d_stiffness.value()),
          "stiffness");
}

}  // namespace externaldemo
