// SPDX-License-Identifier: MIT
#include "TensorMass/kernels/TensorMassRemoval.h"

#include <algorithm>

#include "TensorMass/kernels/TetrahedronTensors.h"
#include "topology/MeshAdjacency.h"

namespace stroma::tensormass {

// --- PrimitiveUses ---------------------------------------------------------------------------

std::uint64_t PrimitiveUses::edgeKey(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

std::array<Index, 3> PrimitiveUses::triangleKey(Index a, Index b, Index c) {
  std::array<Index, 3> key{a, b, c};
  std::sort(key.begin(), key.end());
  return key;
}

std::size_t PrimitiveUses::TriangleKeyHash::operator()(const std::array<Index, 3>& key) const {
  return (std::size_t{key[0]} * 0x9E3779B97F4A7C15ull) ^
         (std::size_t{key[1]} * 0xC2B2AE3D27D4EB4Full) ^
         (std::size_t{key[2]} * 0x165667B19E3779F9ull);
}

void PrimitiveUses::build(std::span<const Tetrahedron> tetrahedra, std::span<const Edge> edges,
                          std::span<const Triangle> triangles) {
  m_edgeIndex.clear();
  m_triangleIndex.clear();
  m_edgeIndex.reserve(edges.size());
  m_triangleIndex.reserve(triangles.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    m_edgeIndex[edgeKey(edges[e][0], edges[e][1])] = static_cast<Index>(e);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    m_triangleIndex[triangleKey(triangles[f][0], triangles[f][1], triangles[f][2])] =
        static_cast<Index>(f);
  m_edgeUses.assign(edges.size(), 0);
  m_triangleUses.assign(triangles.size(), 0);
  for (const Tetrahedron& t : tetrahedra) {
    for (const auto& local : kTetrahedronEdges)
      if (const Index e = edge(t[local[0]], t[local[1]]); e != kInvalidIndex) ++m_edgeUses[e];
    for (const auto& local : kTetrahedronFaces)
      if (const Index f = triangle(t[local[0]], t[local[1]], t[local[2]]); f != kInvalidIndex)
        ++m_triangleUses[f];
  }
}

Index PrimitiveUses::edge(Index a, Index b) const {
  const auto it = m_edgeIndex.find(edgeKey(a, b));
  return it == m_edgeIndex.end() ? kInvalidIndex : it->second;
}

Index PrimitiveUses::triangle(Index a, Index b, Index c) const {
  const auto it = m_triangleIndex.find(triangleKey(a, b, c));
  return it == m_triangleIndex.end() ? kInvalidIndex : it->second;
}

void PrimitiveUses::removeEdge(Index e, std::vector<Edge>& edges) {
  m_edgeIndex.erase(edgeKey(edges[e][0], edges[e][1]));
  const auto last = static_cast<Index>(edges.size() - 1);
  if (e != last) {
    edges[e] = edges[last];
    m_edgeUses[e] = m_edgeUses[last];
    m_edgeIndex[edgeKey(edges[e][0], edges[e][1])] = e;
  }
  edges.pop_back();
  m_edgeUses.pop_back();
}

void PrimitiveUses::removeTriangle(Index f, std::vector<Triangle>& triangles) {
  m_triangleIndex.erase(triangleKey(triangles[f][0], triangles[f][1], triangles[f][2]));
  const auto last = static_cast<Index>(triangles.size() - 1);
  if (f != last) {
    triangles[f] = triangles[last];
    m_triangleUses[f] = m_triangleUses[last];
    m_triangleIndex[triangleKey(triangles[f][0], triangles[f][1], triangles[f][2])] = f;
  }
  triangles.pop_back();
  m_triangleUses.pop_back();
}

namespace {

/// Moves the data of the last primitive into slot i and drops the last (as removeEdge does).
template <class T>
void removeSlot(std::vector<T>& values, Index i) {
  if (static_cast<std::size_t>(i) + 1 != values.size()) values[i] = values.back();
  values.pop_back();
}

}  // namespace

// --- Linear ----------------------------------------------------------------------------------

void removeFromLinearTensorMass(std::span<const Tetrahedron> removed,
                                std::span<const fem::TetrahedronShape> shapes,
                                const fem::LameParameters& lame, std::span<const Index> freedPoints,
                                VertexEdgeTensors& tensors, PrimitiveUses& uses) {
  // 1. Subtract each removed tetrahedron's K^pp and K^pj (eq. 1.11), edges in their stored
  //    orientation; note the edges no tetrahedron uses anymore.
  std::vector<Index> unused;
  for (std::size_t r = 0; r < removed.size(); ++r) {
    const Tetrahedron& v = removed[r];
    const TetrahedronTensors T(shapes[r], lame);
    for (int p = 0; p < 4; ++p) tensors.vertexTensors[v[p]] -= T.stiffness(p, p);
    for (const auto& local : kTetrahedronEdges) {
      const Index e = uses.edge(v[local[0]], v[local[1]]);
      if (e == kInvalidIndex) continue;
      const int p = localVertex(v, tensors.edges[e][0]), j = localVertex(v, tensors.edges[e][1]);
      tensors.edgeTensors[e] -= T.stiffness(p, j);
      if (uses.releaseEdge(e)) unused.push_back(e);
    }
  }
  // 2. Drop them, from the highest index down (each slot receives the last edge).
  std::sort(unused.begin(), unused.end(), std::greater<>());
  for (Index e : unused) {
    removeSlot(tensors.edgeTensors, e);
    uses.removeEdge(e, tensors.edges);
  }
  for (Index p : freedPoints) tensors.vertexTensors[p].setZero();
}

// --- St Venant-Kirchhoff ---------------------------------------------------------------------

void removeFromStVKTensorMass(std::span<const Index> removed,
                              std::span<const fem::TetrahedronShape> shapes,
                              const fem::LameParameters& lame, std::span<const Index> freedPoints,
                              StVKTensorMass& model, PrimitiveUses& uses) {
  // 1. Subtract each tetrahedron's terms from its vertices, edges and triangles, and remove it
  //    with its own terms (the last tetrahedron into its slot). The edge indices stay valid
  //    meanwhile: unused edges and triangles are only noted.
  std::vector<Index> unusedEdges, unusedTriangles;
  for (std::size_t r = 0; r < removed.size(); ++r) {
    const Index t = removed[r];
    const Tetrahedron v = model.tetrahedra[t];
    std::array<Index, 4> triangles;
    for (int f = 0; f < 4; ++f) {
      const auto& local = kTetrahedronFaces[f];
      triangles[f] = uses.triangle(v[local[0]], v[local[1]], v[local[2]]);
    }
    addStVKTetrahedronTerms(v, TetrahedronTensors(shapes[r], lame), model.tetrahedronEdges[t],
                            triangles, -1.0, model);
    for (Index e : model.tetrahedronEdges[t])
      if (uses.releaseEdge(e)) unusedEdges.push_back(e);
    for (Index f : triangles)
      if (uses.releaseTriangle(f)) unusedTriangles.push_back(f);
    removeSlot(model.tetrahedra, t);
    removeSlot(model.tetrahedronTerms, t);
    removeSlot(model.tetrahedronEdges, t);
  }
  // 2. Drop the unused triangles and edges, from the highest index down.
  std::sort(unusedTriangles.begin(), unusedTriangles.end(), std::greater<>());
  for (Index f : unusedTriangles) {
    removeSlot(model.triangleTerms, f);
    removeSlot(model.triangleEdges, f);
    uses.removeTriangle(f, model.triangles);
  }
  std::sort(unusedEdges.begin(), unusedEdges.end(), std::greater<>());
  for (Index e : unusedEdges) {
    removeSlot(model.edgeTerms, e);
    uses.removeEdge(e, model.edges);
  }
  // 3. Edges moved: re-derive the edge indices of the triangles and tetrahedra.
  if (!unusedEdges.empty()) {
    for (std::size_t f = 0; f < model.triangles.size(); ++f) {
      const Triangle& t = model.triangles[f];
      model.triangleEdges[f] = {uses.edge(t[0], t[1]), uses.edge(t[1], t[2]),
                                uses.edge(t[0], t[2])};
    }
    for (std::size_t t = 0; t < model.tetrahedra.size(); ++t)
      for (int e = 0; e < 6; ++e)
        model.tetrahedronEdges[t][e] = uses.edge(model.tetrahedra[t][kTetrahedronEdges[e][0]],
                                                 model.tetrahedra[t][kTetrahedronEdges[e][1]]);
  }
  for (Index p : freedPoints) model.vertices[p] = {};
}

}  // namespace stroma::tensormass
