// SPDX-License-Identifier: MIT
#pragma once

#include "ModelSupport.h"
#include "core/Link.h"
#include "core/StateTypes.h"

namespace stroma {

/// The triangles of the node's topology, over its Vec3d state, as collision primitives (SOFA's
/// TriangleCollisionModel): the topology's triangles and each quad as two triangles (0 1 2,
/// 0 2 3); for a volume mesh (tetrahedra or hexahedra, a grid), its boundary faces, oriented
/// outwards. They collide on the side of their normal (right-hand rule) unless `bothSide`.
class TriangleCollisionModel final : public CollisionModel {
 public:
  Link<Topology> l_topology{this, "topology",
                            "Mesh whose triangles (and quads) are the primitives (default: the "
                            "nearest topology from the node up)."};
  Data<bool> d_computeNormals{this, "computeNormals", true,
                              "SOFA option, accepted: normals are always computed."};

  void init() override;
  BaseMechanicalState* state() const override { return m_state; }
  void updateGeometry() override;

 private:
  void updateTriangles();

  MechanicalState<Vec3Types>* m_state = nullptr;
  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = ~std::uint64_t{0};
  std::vector<std::array<std::uint32_t, 3>> m_triangles;
  std::vector<std::uint8_t> m_ownership;
  std::vector<std::uint32_t> m_edgeNeighbors;  // 3 per triangle
  collision::NeighborLists m_ring;             // each point's neighbours on the triangles
  std::vector<Vec3d> m_normals;
};

}  // namespace stroma
