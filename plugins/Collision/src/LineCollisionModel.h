// SPDX-License-Identifier: MIT
#pragma once

#include "ModelSupport.h"
#include "core/Link.h"
#include "core/StateTypes.h"

namespace stroma {

/// The edges of the node's topology, over its Vec3d state, as collision segments (SOFA's
/// LineCollisionModel): every edge of the topology (given edges and those of its elements).
/// Each edge knows the third vertices of the triangles around it (LocalMinDistance).
class LineCollisionModel final : public CollisionModel {
 public:
  Link<Topology> l_topology{this, "topology",
                            "Mesh whose edges are the segments (default: the nearest topology "
                            "from the node up)."};

  void init() override;
  BaseMechanicalState* state() const override { return m_state; }
  void updateGeometry() override;

 private:
  void updateEdges();

  MechanicalState<Vec3Types>* m_state = nullptr;
  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = ~std::uint64_t{0};
  collision::NeighborLists m_neighbors;
};

}  // namespace stroma
