// SPDX-License-Identifier: MIT
#pragma once

#include "ModelSupport.h"
#include "core/Link.h"
#include "core/StateTypes.h"

namespace stroma {

/// The points of the node's Vec3d state as collision primitives (SOFA's PointCollisionModel).
/// With a topology in the node or above, each point knows its neighbours (LocalMinDistance).
class PointCollisionModel final : public CollisionModel {
 public:
  Link<Topology> l_topology{this, "topology",
                            "Mesh whose edges give each point's neighbours, for "
                            "LocalMinDistance (default: the nearest topology from the node up)."};

  void init() override;
  BaseMechanicalState* state() const override { return m_state; }
  void updateGeometry() override;

 private:
  void updateNeighbors();

  MechanicalState<Vec3Types>* m_state = nullptr;
  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = ~std::uint64_t{0};
  collision::NeighborLists m_neighbors;
};

}  // namespace stroma
