// SPDX-License-Identifier: MIT
#pragma once

#include <string_view>

namespace stroma {

class Node;

/// An action over the scene graph. traverse() calls processNodeTopDown on a node before its
/// children and processNodeBottomUp after them, children in scene order. Returning prune from
/// processNodeTopDown skips the node's subtree (its processNodeBottomUp is still called).
/// Nodes with activated="false" are skipped entirely.
class Visitor {
 public:
  enum class Result { carryOn, prune };

  virtual ~Visitor() = default;
  virtual Result processNodeTopDown(Node& node) {
    (void)node;
    return Result::carryOn;
  }
  virtual void processNodeBottomUp(Node& node) { (void)node; }
  /// For timing and debugging output.
  virtual std::string_view name() const = 0;
};

/// Runs `visitor` over the subtree rooted at `node`.
void traverse(Node& node, Visitor& visitor);

}  // namespace stroma
