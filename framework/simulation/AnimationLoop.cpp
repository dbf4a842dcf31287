// SPDX-License-Identifier: MIT
#include "simulation/AnimationLoop.h"

#include "core/Node.h"
#include "simulation/Timing.h"
#include "simulation/Visitor.h"

namespace stroma {

namespace {

class BehaviorUpdateVisitor final : public Visitor {
 public:
  explicit BehaviorUpdateVisitor(double dt) : m_dt(dt) {}
  Result processNodeTopDown(Node& node) override {
    for (BehaviorModel* model : node.getAll<BehaviorModel>()) model->updatePosition(m_dt);
    return Result::carryOn;
  }
  std::string_view name() const override { return "behaviorUpdate"; }

 private:
  double m_dt;
};

}  // namespace

void animateDefault(Node& root, double dt, Timing& timing) {
  {
    ScopedPhase phase(timing, "behaviorModels");
    BehaviorUpdateVisitor visitor(dt);
    traverse(root, visitor);
  }
  root.setTime(root.time() + dt);
}

}  // namespace stroma
