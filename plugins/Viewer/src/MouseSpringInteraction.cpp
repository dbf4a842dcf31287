// SPDX-License-Identifier: MIT
#include "MouseSpringInteraction.h"

#include <memory>

#include "core/Node.h"
#include "simulation/Mass.h"

namespace stroma::viewer {

double grabbedBodyMass(const Vec3State& state) {
  const Node* node = state.node();
  BaseMass* mass = node ? node->getUp<BaseMass>() : nullptr;
  if (!mass || mass->states().empty()) return 0;
  auto* massState = dynamic_cast<Vec3State*>(mass->states().front());
  if (!massState) return 0;
  // A temporary vector holds the unit velocity: no solver keeps temporaries between steps.
  const VecId unit = VecId::deriv(VecId::kFirstTemporary);
  massState->vAlloc(unit);
  for (Vec3d& v : massState->writeDeriv(unit)) v = Vec3d::UnitX();
  const double total = 2 * mass->kineticEnergyAt(unit);
  massState->vFree(unit);
  return total;
}

bool MouseSpringInteraction::grab(const PickedPoint& picked, const Vec3d& target,
                                  double stiffness) {
  release();
  Node* node = picked.state ? picked.state->node() : nullptr;
  if (!node) return false;
  if (stiffness <= 0) {
    const double mass = grabbedBodyMass(*picked.state);
    stiffness = mass > 0 ? kSpringStiffnessPerKilogram * mass : kDefaultSpringStiffness;
  }
  auto spring = std::make_unique<MouseSpringForceField>();
  spring->setName("mouseSpring");
  spring->setClassName("MouseSpringForceField", "Vec3d");
  spring->l_mstate.set(picked.state);
  spring->d_index.setValue(static_cast<unsigned>(picked.index));
  spring->d_target.setValue(target);
  spring->d_stiffness.setValue(stiffness);
  auto* added = static_cast<MouseSpringForceField*>(&node->addObject(std::move(spring)));
  added->init();
  if (!added->isValid()) {
    node->removeObject(added);
    return false;
  }
  m_spring = added;
  m_picked = picked;
  return true;
}

void MouseSpringInteraction::moveTarget(const Vec3d& target) {
  if (m_spring) m_spring->d_target.setValue(target);
}

void MouseSpringInteraction::release() {
  if (!m_spring) return;
  if (Node* node = m_spring->node()) node->removeObject(m_spring);
  m_spring = nullptr;
}

}  // namespace stroma::viewer
