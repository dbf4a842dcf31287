// SPDX-License-Identifier: MIT
#include "topology/MeshAdjacency.h"

#include <algorithm>
#include <unordered_map>

namespace stroma {

namespace {

/// An edge as one key, independent of its orientation.
std::uint64_t edgeKey(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

/// A face as one key, independent of its orientation and first vertex: its sorted vertices.
template <std::size_t N>
std::array<Index, N> faceKey(std::array<Index, N> face) {
  std::sort(face.begin(), face.end());
  return face;
}

template <std::size_t N>
struct FaceKeyHash {
  std::size_t operator()(const std::array<Index, N>& key) const {
    // FNV-1a over the indices: cheap, and good enough for the keys of a mesh.
    std::uint64_t h = 1469598103934665603ull;
    for (Index v : key) {
      h ^= v;
      h *= 1099511628211ull;
    }
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

/// Numbers the edges of `elements` in order of first appearance.
template <std::size_t N, std::size_t E>
ElementEdges<E> uniqueEdges(std::span<const std::array<Index, N>> elements,
                            const std::array<std::array<int, 2>, E>& table) {
  ElementEdges<E> result;
  result.edgesInElement.resize(elements.size());
  std::unordered_map<std::uint64_t, Index> ids;
  ids.reserve(elements.size() * E / 2 + 1);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto& element = elements[e];
    for (std::size_t j = 0; j < E; ++j) {
      const Index a = element[table[j][0]];
      const Index b = element[table[j][1]];
      const auto [it, inserted] =
          ids.try_emplace(edgeKey(a, b), static_cast<Index>(result.edges.size()));
      if (inserted) result.edges.push_back({a, b});
      result.edgesInElement[e][j] = it->second;
    }
  }
  return result;
}

/// Numbers the faces of `elements` in order of first appearance and links faces and elements.
template <class Face, std::size_t N, std::size_t F>
ElementFaces<Face, F> uniqueFaces(
    std::span<const std::array<Index, N>> elements,
    const std::array<std::array<int, std::tuple_size_v<Face>>, F>& table) {
  constexpr std::size_t K = std::tuple_size_v<Face>;
  ElementFaces<Face, F> result;
  result.facesInElement.resize(elements.size());
  std::unordered_map<Face, Index, FaceKeyHash<K>> ids;
  ids.reserve(elements.size() * F / 2 + 1);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    for (std::size_t j = 0; j < F; ++j) {
      Face face;
      for (std::size_t k = 0; k < K; ++k) face[k] = elements[e][table[j][k]];
      const auto [it, inserted] =
          ids.try_emplace(faceKey(face), static_cast<Index>(result.faces.size()));
      if (inserted) result.faces.push_back(face);
      result.facesInElement[e][j] = it->second;
    }
  }
  // Elements around each face: a counting sort over facesInElement keeps them in order.
  const std::size_t nbFaces = result.faces.size();
  AdjacencyList& around = result.elementsAroundFace;
  around.offsets.assign(nbFaces + 1, 0);
  for (const auto& faces : result.facesInElement)
    for (Index f : faces) ++around.offsets[f + 1];
  for (std::size_t i = 0; i < nbFaces; ++i) around.offsets[i + 1] += around.offsets[i];
  around.items.resize(around.offsets[nbFaces]);
  std::vector<Index> next(around.offsets.begin(), around.offsets.end() - 1);
  for (std::size_t e = 0; e < result.facesInElement.size(); ++e)
    for (Index f : result.facesInElement[e]) around.items[next[f]++] = static_cast<Index>(e);
  return result;
}

template <class Face, std::size_t F>
std::vector<Face> boundaryOf(const ElementFaces<Face, F>& faces) {
  std::vector<Face> boundary;
  for (std::size_t f = 0; f < faces.faces.size(); ++f)
    if (faces.elementsAroundFace[f].size() == 1) boundary.push_back(faces.faces[f]);
  return boundary;
}

}  // namespace

ElementEdges<3> computeTriangleEdges(std::span<const Triangle> triangles) {
  return uniqueEdges(triangles, kTriangleEdges);
}

ElementEdges<4> computeQuadEdges(std::span<const Quad> quads) {
  return uniqueEdges(quads, kQuadEdges);
}

ElementEdges<6> computeTetrahedronEdges(std::span<const Tetrahedron> tetrahedra) {
  return uniqueEdges(tetrahedra, kTetrahedronEdges);
}

ElementEdges<12> computeHexahedronEdges(std::span<const Hexahedron> hexahedra) {
  return uniqueEdges(hexahedra, kHexahedronEdges);
}

TetrahedronFaces computeTetrahedronFaces(std::span<const Tetrahedron> tetrahedra) {
  return uniqueFaces<Triangle>(tetrahedra, kTetrahedronFaces);
}

HexahedronFaces computeHexahedronFaces(std::span<const Hexahedron> hexahedra) {
  return uniqueFaces<Quad>(hexahedra, kHexahedronFaces);
}

std::vector<Triangle> computeBoundaryTriangles(std::span<const Tetrahedron> tetrahedra) {
  return boundaryOf(computeTetrahedronFaces(tetrahedra));
}

std::vector<Quad> computeBoundaryQuads(std::span<const Hexahedron> hexahedra) {
  return boundaryOf(computeHexahedronFaces(hexahedra));
}

std::vector<Edge> computeBoundaryEdges(std::span<const Triangle> triangles) {
  const ElementEdges<3> edges = computeTriangleEdges(triangles);
  std::vector<Index> uses(edges.edges.size(), 0);
  for (const auto& inTriangle : edges.edgesInElement)
    for (Index e : inTriangle) ++uses[e];
  std::vector<Edge> boundary;
  for (std::size_t e = 0; e < edges.edges.size(); ++e)
    if (uses[e] == 1) boundary.push_back(edges.edges[e]);
  return boundary;
}

std::vector<Edge> computeAllEdges(std::span<const Edge> edges, std::span<const Triangle> triangles,
                                  std::span<const Quad> quads,
                                  std::span<const Tetrahedron> tetrahedra,
                                  std::span<const Hexahedron> hexahedra) {
  std::vector<Edge> result;
  std::unordered_map<std::uint64_t, Index> seen;
  auto add = [&](Index a, Index b) {
    if (seen.try_emplace(edgeKey(a, b), static_cast<Index>(result.size())).second)
      result.push_back({a, b});
  };
  for (const Edge& e : edges) add(e[0], e[1]);
  auto addAll = [&](const auto& elements, const auto& table) {
    for (const auto& element : elements)
      for (const auto& local : table) add(element[local[0]], element[local[1]]);
  };
  addAll(triangles, kTriangleEdges);
  addAll(quads, kQuadEdges);
  addAll(tetrahedra, kTetrahedronEdges);
  addAll(hexahedra, kHexahedronEdges);
  return result;
}

}  // namespace stroma
