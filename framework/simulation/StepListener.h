// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

namespace stroma {

class Node;

/// A component that works between steps, whatever the scene's animation loop: exporters, state
/// writers and readers (SOFA's listeners of AnimateBeginEvent and AnimateEndEvent). Scene::step
/// calls every listener of the graph, in graph order (depth first, scene order within a
/// node), before and after the loop's step. A scene without listeners pays nothing: the scene
/// looks for them once, after loading.
///
/// Listeners never change what the step computes unless that is their purpose (ReadState sets
/// a state); they run on the calling thread, outside the step's timed phases.
class StepListener {
 public:
  virtual ~StepListener() = default;
  /// Before the step that starts at `time` (the root's time) and lasts `dt`.
  virtual void stepBegin(double /*time*/, double /*dt*/) {}
  /// After the step, at the new `time`.
  virtual void stepEnd(double /*time*/, double /*dt*/) {}
};

/// Every StepListener under `root`, in the order Scene::step calls them.
void collectStepListeners(Node& root, std::vector<StepListener*>& listeners);

}  // namespace stroma
