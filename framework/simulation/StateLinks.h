// SPDX-License-Identifier: MIT
// Finding a component's state from a link (a state, or a node holding one; by default the
// component's own node's): the Lagrangian constraints and the URDF joint limits use it.
#pragma once

#include <string>

#include "core/Link.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"

namespace stroma {

/// The state `link` names (or holds, for a node); without a link, the one in `owner`'s node.
/// Reports an error naming `field` and returns nullptr when there is none of this type.
template <class DataTypes>
MechanicalState<DataTypes>* resolveState(Base& owner, const Link<Base>& link, const char* field) {
  Base* target = link.get();
  if (!link) target = owner.node() ? owner.node()->template get<MechanicalState<DataTypes>>() : nullptr;
  if (auto* n = dynamic_cast<Node*>(target)) target = n->template get<MechanicalState<DataTypes>>();
  auto* state = dynamic_cast<MechanicalState<DataTypes>*>(target);
  if (!state)
    owner.msgError(std::string("needs a ") + DataTypes::name + " mechanical state: " +
                       (link ? link->path() + " is not one (nor a node holding one)"
                             : std::string("none in its node; give ") + field),
                   field);
  return state;
}

}  // namespace stroma
