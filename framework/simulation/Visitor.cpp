// SPDX-License-Identifier: MIT
#include "simulation/Visitor.h"

#include "core/Node.h"

namespace stroma {

void traverse(Node& node, Visitor& visitor) {
  if (!node.d_activated.value()) return;
  if (visitor.processNodeTopDown(node) == Visitor::Result::carryOn)
    for (const auto& child : node.children()) traverse(*child, visitor);
  visitor.processNodeBottomUp(node);
}

}  // namespace stroma
