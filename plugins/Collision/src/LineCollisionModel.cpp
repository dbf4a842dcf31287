// SPDX-License-Identifier: MIT
#include "LineCollisionModel.h"

namespace stroma {

void LineCollisionModel::init() {
  m_geometry.kind = PrimitiveKind::line;
  m_state = collision::findModelState<Vec3Types>(*this);
  m_topology = collision::findModelTopology(*this, l_topology);
  if (!m_state) return;
  if (!m_topology || m_topology->allEdges().empty()) {
    msgError(
        "needs edges: a topology with edges or elements (MeshTopology, "
        "TriangleSetTopologyContainer, ...) in its node or above, or a 'topology' link",
        "topology");
    return;
  }
  updateEdges();
  if (isValid()) updateGeometry();
}

void LineCollisionModel::updateEdges() {
  if (m_topology->revision() == m_topologyRevision) return;
  m_topologyRevision = m_topology->revision();
  const std::vector<Edge>& edges = m_topology->allEdges();
  if (!collision::checkElementIndices<2>(*this, edges, m_state->size(), "edge")) return;
  m_neighbors = collision::edgeOppositeVertices(edges, m_topology->triangles());
  m_geometry.edges = edges;
  m_geometry.neighborOffsets = m_neighbors.offsets;
  m_geometry.neighbors = m_neighbors.entries;
}

void LineCollisionModel::updateGeometry() {
  if (!m_state || !m_topology) return;
  updateEdges();
  m_geometry.points = m_state->readCoord(VecId::position());
}

}  // namespace stroma
