// SPDX-License-Identifier: MIT
// Adjacency of mesh elements: unique edges and faces, boundary faces, elements around each
// vertex. Free functions over plain element lists, independent of any component, so that
// they are testable alone and reusable (Topology caches their results).
//
// Every result is deterministic: unique edges and faces are numbered in order of first
// appearance when the elements are scanned in order, each element's local edges and faces
// in the order of the tables below; lists around a vertex are in increasing element order.
// Indices past the points (>= nbPoints where a count is given) are skipped, not reported:
// Topology reports them.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "topology/TopologyTypes.h"

namespace stroma {

// --- Local numbering of sub-elements (vertex positions inside the element) --------------------

/// Edge i of a triangle is opposite vertex i.
inline constexpr std::array<std::array<int, 2>, 3> kTriangleEdges{{{1, 2}, {2, 0}, {0, 1}}};
inline constexpr std::array<std::array<int, 2>, 4> kQuadEdges{{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
inline constexpr std::array<std::array<int, 2>, 6> kTetrahedronEdges{
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
/// Bottom face, top face, then the four vertical edges.
// clang-format off
inline constexpr std::array<std::array<int, 2>, 12> kHexahedronEdges{{
    {0, 1}, {1, 2}, {2, 3}, {3, 0},
    {4, 5}, {5, 6}, {6, 7}, {7, 4},
    {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
// clang-format on
/// Face i of a tetrahedron is opposite vertex i, oriented outwards for a positive tetrahedron.
inline constexpr std::array<std::array<int, 3>, 4> kTetrahedronFaces{
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
/// Faces w=0, w=1, v=0, u=1, v=1, u=0 (see TopologyTypes.h), oriented outwards.
inline constexpr std::array<std::array<int, 4>, 6> kHexahedronFaces{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

// --- Result types --------------------------------------------------------------------------

/// Lists of indices per item, stored compactly: the list of item i is
/// items[offsets[i]] .. items[offsets[i + 1] - 1].
struct AdjacencyList {
  std::vector<Index> offsets{0};  ///< (n + 1)
  std::vector<Index> items;

  std::size_t size() const { return offsets.size() - 1; }
  std::span<const Index> operator[](std::size_t i) const {
    return {items.data() + offsets[i], items.data() + offsets[i + 1]};
  }
};

/// The unique edges of a set of elements, and the edges of each element.
template <std::size_t EdgesPerElement>
struct ElementEdges {
  /// Unique edges, oriented as in the first element that has them.
  std::vector<Edge> edges;
  /// (elements x EdgesPerElement) indices into `edges`, in the local order of the edge table.
  std::vector<std::array<Index, EdgesPerElement>> edgesInElement;
};

/// The unique faces of a set of volume elements, and how they connect.
template <class Face, std::size_t FacesPerElement>
struct ElementFaces {
  /// Unique faces, oriented outwards from the first element that has them.
  std::vector<Face> faces;
  /// (elements x FacesPerElement) indices into `faces`, in the local order of the face table.
  std::vector<std::array<Index, FacesPerElement>> facesInElement;
  /// For each face, the elements that have it (1 on the boundary, 2 inside a manifold mesh).
  AdjacencyList elementsAroundFace;
};

using TetrahedronFaces = ElementFaces<Triangle, 4>;
using HexahedronFaces = ElementFaces<Quad, 6>;

// --- Kernels ---------------------------------------------------------------------------------

ElementEdges<3> computeTriangleEdges(std::span<const Triangle> triangles);
ElementEdges<4> computeQuadEdges(std::span<const Quad> quads);
ElementEdges<6> computeTetrahedronEdges(std::span<const Tetrahedron> tetrahedra);
ElementEdges<12> computeHexahedronEdges(std::span<const Hexahedron> hexahedra);

TetrahedronFaces computeTetrahedronFaces(std::span<const Tetrahedron> tetrahedra);
HexahedronFaces computeHexahedronFaces(std::span<const Hexahedron> hexahedra);

/// Faces that belong to exactly one tetrahedron, oriented outwards (for positively oriented
/// tetrahedra), in order of first appearance.
std::vector<Triangle> computeBoundaryTriangles(std::span<const Tetrahedron> tetrahedra);
/// Faces that belong to exactly one hexahedron, oriented outwards, in order of first appearance.
std::vector<Quad> computeBoundaryQuads(std::span<const Hexahedron> hexahedra);

/// Edges that belong to exactly one triangle (the border of a surface), oriented as in their
/// triangle, in order of first appearance.
std::vector<Edge> computeBoundaryEdges(std::span<const Triangle> triangles);

/// Every edge of a mesh: `edges` first (duplicates removed), then the edges of the triangles,
/// quads, tetrahedra and hexahedra that are not already listed.
std::vector<Edge> computeAllEdges(std::span<const Edge> edges, std::span<const Triangle> triangles,
                                  std::span<const Quad> quads,
                                  std::span<const Tetrahedron> tetrahedra,
                                  std::span<const Hexahedron> hexahedra);

/// For each of the `nbPoints` points, the elements that use it, in increasing order.
template <std::size_t N>
AdjacencyList computeElementsAroundVertex(std::span<const std::array<Index, N>> elements,
                                          std::size_t nbPoints) {
  AdjacencyList result;
  result.offsets.assign(nbPoints + 1, 0);
  // Count, prefix-sum, then fill: a counting sort keeps the elements in increasing order.
  for (const auto& element : elements)
    for (Index v : element)
      if (v < nbPoints) ++result.offsets[v + 1];
  for (std::size_t i = 0; i < nbPoints; ++i) result.offsets[i + 1] += result.offsets[i];
  result.items.resize(result.offsets[nbPoints]);
  std::vector<Index> next(result.offsets.begin(), result.offsets.end() - 1);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (Index v : elements[e])
      if (v < nbPoints) result.items[next[v]++] = static_cast<Index>(e);
  return result;
}

}  // namespace stroma
