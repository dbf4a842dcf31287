// SPDX-License-Identifier: MIT
#include "simulation/AnimationLoop.h"

#include "collision/CollisionPipeline.h"
#include "core/Node.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Solvers.h"
#include "simulation/Timing.h"
#include "simulation/Visitor.h"

namespace stroma {

namespace {

class BehaviorUpdateVisitor final : public Visitor {
 public:
  explicit BehaviorUpdateVisitor(double dt) : m_dt(dt) {}
  Result processNodeTopDown(Node& node) override {
    for (const auto& object : node.objects())
      if (auto* model = dynamic_cast<BehaviorModel*>(object.get())) model->updatePosition(m_dt);
    return Result::carryOn;
  }
  std::string_view name() const override { return "behaviorUpdate"; }

 private:
  double m_dt;
};

// Each node with an ODE solver integrates its subtree; sub-nodes with their own solver are
// reached by the traversal and integrate theirs.
class SolveVisitor final : public Visitor {
 public:
  SolveVisitor(double dt, Timing& timing) : m_dt(dt), m_timing(timing) {}
  Result processNodeTopDown(Node& node) override {
    for (const auto& object : node.objects()) {  // not getAll: no list allocated per step
      auto* solver = dynamic_cast<OdeSolver*>(object.get());
      if (!solver || !solver->isValid()) continue;
      MechanicalOperations& mop = solver->operations(node, m_timing, m_dt);
      if (!mop.hasState()) solver->reportNoState();
      // Constraints hold from the start of the step: a point fixed since the last step (its
      // indices changed) starts it at rest instead of drifting one step on its old velocity.
      mop.projectVelocity(VecId::velocity());
      solver->solve(mop, m_dt);
    }
    return Result::carryOn;
  }
  std::string_view name() const override { return "solve"; }

 private:
  double m_dt;
  Timing& m_timing;
};

}  // namespace

void animateDefault(Node& root, double dt, Timing& timing) {
  {
    ScopedPhase phase(timing, "behaviorModels");
    BehaviorUpdateVisitor visitor(dt);
    traverse(root, visitor);
  }
  // Only scenes with a collision pipeline have a collision step (DESIGN.md sections 3 and 4).
  if (CollisionPhase* collision = root.get<CollisionPhase>(); collision && collision->isValid()) {
    ScopedPhase phase(timing, "collision");
    collision->computeCollisions(root, timing);
  }
  {
    ScopedPhase phase(timing, "solve");
    SolveVisitor visitor(dt, timing);
    traverse(root, visitor);
  }
  root.setTime(root.time() + dt);
}

}  // namespace stroma
