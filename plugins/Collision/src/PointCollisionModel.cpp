// SPDX-License-Identifier: MIT
#include "PointCollisionModel.h"

namespace stroma {

void PointCollisionModel::init() {
  m_geometry.kind = PrimitiveKind::point;
  m_state = collision::findModelState<Vec3Types>(*this);
  m_topology = collision::findModelTopology(*this, l_topology);
  if (m_state) updateGeometry();
}

void PointCollisionModel::updateNeighbors() {
  if (!m_topology || m_topology->revision() == m_topologyRevision) return;
  m_topologyRevision = m_topology->revision();
  m_neighbors = collision::pointNeighbors(m_state->size(), m_topology->allEdges(), {});
  m_geometry.neighborOffsets = m_neighbors.offsets;
  m_geometry.neighbors = m_neighbors.entries;
}

void PointCollisionModel::updateGeometry() {
  if (!m_state) return;
  m_geometry.points = m_state->readCoord(VecId::position());
  updateNeighbors();
}

}  // namespace stroma
