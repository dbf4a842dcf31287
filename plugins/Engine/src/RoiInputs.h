// SPDX-License-Identifier: MIT
// What the region-of-interest engines (BoxROI, SphereROI) share: SOFA's search for the inputs a
// scene did not give.
#pragma once

#include "core/Base.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma::roi {

/// Given by the scene: a value or a link.
inline bool isGiven(const BaseData& data) { return data.isSet() || data.parent(); }

/// Makes `data` follow `parent`; false when there is no parent or the types do not convert.
inline bool follow(BaseData& data, BaseData* parent) {
  std::string error;
  return parent && data.setParent(parent, error);
}

/// SOFA's default points of a region of interest: the rest positions of the node's mechanical
/// state, else the positions of a loader of the node, else the rest positions of the nearest
/// state above. Reports an error on `owner` when there is none.
inline void findDefaultPosition(Base& owner, BaseData& position) {
  Node* here = owner.node();
  if (!here || isGiven(position)) return;
  BaseData* source = nullptr;
  if (auto* state = here->get<BaseMechanicalState>()) source = state->findData("rest_position");
  for (const auto& object : here->objects()) {
    if (source) break;
    if (object->className().find("Loader") != std::string::npos)
      source = object->findData("position");
  }
  if (!source)
    if (auto* state = here->getUp<BaseMechanicalState>()) source = state->findData("rest_position");
  if (!follow(position, source))
    owner.msgError(
        "no position given, and no mechanical state or loader to take them from: give "
        "position=\"@dofs.rest_position\" or add a MechanicalObject",
        "position");
}

/// An element list not given follows `source` (a list of the node's topology) when `wanted`.
inline void followTopology(BaseData& elements, bool wanted, const BaseData& source) {
  if (!isGiven(elements) && wanted) follow(elements, const_cast<BaseData*>(&source));
}

}  // namespace stroma::roi
