// SPDX-License-Identifier: MIT
#include "TriangleCollisionModel.h"

#include <algorithm>

namespace stroma {

namespace {

// Which vertices and edges each triangle owns: the first triangle that has a vertex or an edge
// owns it (CollisionGeometry::featureOwnership).
std::vector<std::uint8_t> computeOwnership(std::span<const std::array<std::uint32_t, 3>> triangles,
                                           std::size_t pointCount) {
  std::vector<std::uint8_t> owned(triangles.size(), 0);
  std::vector<char> vertexTaken(pointCount, 0);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;  // (key, triangle * 3 + local)
  edges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = triangles[t][k];
      if (!vertexTaken[v]) {
        vertexTaken[v] = 1;
        owned[t] |= static_cast<std::uint8_t>(1u << k);
      }
      const std::uint64_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      edges.push_back(
          {std::min(a, b) << 32 | std::max(a, b), static_cast<std::uint32_t>(3 * t + k)});
    }
  // Stable sort: within one edge, the first triangle comes first.
  std::stable_sort(edges.begin(), edges.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (i == 0 || edges[i].first != edges[i - 1].first)
      owned[edges[i].second / 3] |= static_cast<std::uint8_t>(1u << (3 + edges[i].second % 3));
  return owned;
}

// For each triangle edge (t, k) = (t[k], t[k + 1]), the third vertex of another triangle on that
// edge, or kNoVertex (the first other one found, when a non-manifold edge has several).
std::vector<std::uint32_t> computeEdgeNeighbors(
    std::span<const std::array<std::uint32_t, 3>> triangles) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;  // (key, triangle * 3 + local)
  edges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      edges.push_back(
          {std::min(a, b) << 32 | std::max(a, b), static_cast<std::uint32_t>(3 * t + k)});
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint32_t> neighbors(3 * triangles.size(), CollisionGeometry::kNoVertex);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = i; b < j; ++b) {
        if (a == b || neighbors[edges[a].second] != CollisionGeometry::kNoVertex) continue;
        const std::uint32_t other = edges[b].second;
        neighbors[edges[a].second] = triangles[other / 3][(other % 3 + 2) % 3];
      }
    i = j;
  }
  return neighbors;
}

}  // namespace

void TriangleCollisionModel::init() {
  m_geometry.kind = PrimitiveKind::triangle;
  m_state = collision::findModelState<Vec3Types>(*this);
  m_topology = collision::findModelTopology(*this, l_topology);
  if (!m_state) return;
  if (!m_topology || (m_topology->triangles().empty() && m_topology->quads().empty() &&
                      m_topology->tetrahedra().empty() && m_topology->hexahedra().empty())) {
    msgError(std::string("needs triangles: a topology with triangles, quads or volume elements "
                         "in its node or above, or a 'topology' link") +
                 (m_topology ? " (" + m_topology->path() + " has none)" : std::string()),
             "topology");
    return;
  }
  updateTriangles();
  if (isValid()) updateGeometry();
}

void TriangleCollisionModel::updateTriangles() {
  if (m_topology->revision() == m_topologyRevision) return;
  m_topologyRevision = m_topology->revision();
  m_triangles.clear();
  auto addQuads = [&](std::span<const Quad> quads) {
    for (const Quad& q : quads) {
      m_triangles.push_back({q[0], q[1], q[2]});
      m_triangles.push_back({q[0], q[2], q[3]});
    }
  };
  if (!m_topology->tetrahedra().empty() || !m_topology->hexahedra().empty()) {
    // A volume mesh: its boundary, oriented outwards (a grid's own face lists hold every inner
    // face too, all turned the same way).
    if (!m_topology->tetrahedra().empty()) {
      const auto& faces = m_topology->boundaryTriangles();
      m_triangles.assign(faces.begin(), faces.end());
    }
    if (!m_topology->hexahedra().empty()) addQuads(m_topology->boundaryQuads());
  } else {
    const auto& triangles = m_topology->triangles();
    m_triangles.assign(triangles.begin(), triangles.end());
    addQuads(m_topology->quads());
  }
  if (!collision::checkElementIndices<3>(*this, m_triangles, m_state->size(), "triangle")) return;
  m_ownership = computeOwnership(m_triangles, m_state->size());
  m_edgeNeighbors = computeEdgeNeighbors(m_triangles);
  m_ring = collision::pointNeighbors(
      m_state->size(), {}, std::span<const Triangle>(m_triangles.data(), m_triangles.size()));
  m_normals.resize(m_triangles.size());
  m_geometry.triangles = m_triangles;
  m_geometry.featureOwnership = m_ownership;
  m_geometry.triangleEdgeNeighbors = m_edgeNeighbors;
  m_geometry.neighborOffsets = m_ring.offsets;
  m_geometry.neighbors = m_ring.entries;
  m_geometry.triangleNormals = m_normals;
}

void TriangleCollisionModel::updateGeometry() {
  if (!m_state || !m_topology || !isValid()) return;
  updateTriangles();
  // The line and point models beside it (initialized by now: the first call is at the first step
  // or after init, and a sibling later in the node reports its kind only after its own init).
  m_geometry.edgesElsewhere = m_geometry.verticesElsewhere = false;
  for (const auto& object : node()->objects()) {
    const auto* other = dynamic_cast<const CollisionModel*>(object.get());
    if (!other || other == this || other->state() != m_state || !other->d_active.value()) continue;
    if (other->geometry().kind == PrimitiveKind::line) m_geometry.edgesElsewhere = true;
    if (other->geometry().kind == PrimitiveKind::point) m_geometry.verticesElsewhere = true;
  }
  const auto& x = m_state->readCoord(VecId::position());
  m_geometry.points = x;
  for (std::size_t t = 0; t < m_triangles.size(); ++t) {
    const auto& tri = m_triangles[t];
    const Vec3d n = (x[tri[1]] - x[tri[0]]).cross(x[tri[2]] - x[tri[0]]);
    const double length = n.norm();
    m_normals[t] = length > 0 ? Vec3d(n / length) : Vec3d::Zero();
  }
}

}  // namespace stroma
