// SPDX-License-Identifier: MIT
#include "simulation/StepListener.h"

#include "core/Node.h"

namespace stroma {

void collectStepListeners(Node& root, std::vector<StepListener*>& listeners) {
  for (const auto& object : root.objects())
    if (auto* listener = dynamic_cast<StepListener*>(object.get())) listeners.push_back(listener);
  for (const auto& child : root.children()) collectStepListeners(*child, listeners);
}

}  // namespace stroma
