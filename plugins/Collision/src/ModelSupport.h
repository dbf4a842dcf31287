// SPDX-License-Identifier: MIT
// What the collision models share: finding their state and topology, and the neighbour lists
// of LocalMinDistance. Free functions, not a base class (STYLE.md section 4).
#pragma once

#include <cstdint>
#include <vector>

#include "collision/CollisionModel.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma::collision {

/// The state of template DataTypes in `model`'s node or the nearest above (as SOFA's context
/// gives it), or nullptr after an error naming what is missing.
template <class DataTypes>
MechanicalState<DataTypes>* findModelState(CollisionModel& model) {
  auto* state = model.node() ? model.node()->template getUp<MechanicalState<DataTypes>>() : nullptr;
  if (!state)
    model.msgError(std::string("needs a mechanical state of template ") + DataTypes::name +
                   " in its node (" + (model.node() ? model.node()->path() : "?") +
                   ") or above: the points its primitives are made of");
  return state;
}

/// The topology of the model: its `topology` link, else the nearest one from its node up;
/// nullptr when there is none.
const Topology* findModelTopology(const CollisionModel& model, const Link<Topology>& link);

/// Neighbour lists in CSR form (CollisionGeometry::neighborOffsets, neighbors).
struct NeighborLists {
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> entries;
};

/// The points joined to each of `pointCount` points by an edge (of the edges of `edges` and of
/// the triangles).
NeighborLists pointNeighbors(std::size_t pointCount, std::span<const Edge> edges,
                             std::span<const Triangle> triangles);
/// For each edge of `edges`, the third vertex of every triangle that has it.
NeighborLists edgeOppositeVertices(std::span<const Edge> edges,
                                   std::span<const Triangle> triangles);

/// Checks that every index of the elements is below `pointCount`; otherwise an error naming
/// the first bad element and returns false.
template <std::size_t N>
bool checkElementIndices(CollisionModel& model, std::span<const std::array<Index, N>> elements,
                         std::size_t pointCount, const char* what) {
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (Index i : elements[e])
      if (i >= pointCount) {
        model.msgError(std::string(what) + " " + std::to_string(e) + " uses point " +
                       std::to_string(i) + ", but the state " +
                       (model.state() ? model.state()->path() : std::string("?")) + " has " +
                       std::to_string(pointCount) + " points");
        return false;
      }
  return true;
}

}  // namespace stroma::collision
