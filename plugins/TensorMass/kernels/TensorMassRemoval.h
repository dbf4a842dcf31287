// SPDX-License-Identifier: MIT
// Following the removal of tetrahedra (cutting, seed 000 section 3.5) in the tensor-mass
// models: the removed tetrahedra's contributions are subtracted from the tensors of their
// vertices, edges and triangles (eq. 1.11 and table 1 of seed 004, in reverse), their own
// terms go with them, and the edges and triangles that no tetrahedron uses anymore are dropped
// (the last one moving into the freed slot). The tensors of untouched primitives are not
// recomputed: the cost is proportional to the removed tetrahedra, plus a pass that re-derives
// the edge indices of the triangles and tetrahedra (hash look-ups, no tensor computation).
// The result equals a build on the remaining tetrahedra to round-off, up to the order and the
// orientation in which the primitives are stored.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "TensorMass/kernels/LinearTensorMass.h"
#include "TensorMass/kernels/StVKTensorMass.h"

namespace stroma::tensormass {

/// The edges and triangles of a model by their vertices (any order), with the number of
/// tetrahedra that use each.
class PrimitiveUses {
 public:
  /// From the tetrahedra and the model's edge and triangle lists (triangles may be empty).
  void build(std::span<const Tetrahedron> tetrahedra, std::span<const Edge> edges,
             std::span<const Triangle> triangles);

  /// The index of the edge (a, b) or (b, a); kInvalidIndex when absent.
  Index edge(Index a, Index b) const;
  /// The index of the triangle on these vertices; kInvalidIndex when absent.
  Index triangle(Index a, Index b, Index c) const;

  /// One tetrahedron fewer uses it; true when none does anymore.
  bool releaseEdge(Index e) { return --m_edgeUses[e] == 0; }
  bool releaseTriangle(Index f) { return --m_triangleUses[f] == 0; }

  /// Removes edge `e` from `edges` (the last one moves into its slot) and from the index.
  void removeEdge(Index e, std::vector<Edge>& edges);
  void removeTriangle(Index f, std::vector<Triangle>& triangles);

 private:
  static std::uint64_t edgeKey(Index a, Index b);
  struct TriangleKeyHash {
    std::size_t operator()(const std::array<Index, 3>& key) const;
  };
  static std::array<Index, 3> triangleKey(Index a, Index b, Index c);

  std::unordered_map<std::uint64_t, Index> m_edgeIndex;
  std::unordered_map<std::array<Index, 3>, Index, TriangleKeyHash> m_triangleIndex;
  std::vector<Index> m_edgeUses, m_triangleUses;
};

/// Linear model (VertexEdgeTensors of eq. 1.11): subtracts the tetrahedra `removed` (their
/// vertices and rest shapes) from `tensors`, drops the edges left unused, and zeroes the
/// tensors of `freedPoints` exactly (no round-off residue). `uses` mirrors tensors.edges.
void removeFromLinearTensorMass(std::span<const Tetrahedron> removed,
                                std::span<const fem::TetrahedronShape> shapes,
                                const fem::LameParameters& lame, std::span<const Index> freedPoints,
                                VertexEdgeTensors& tensors, PrimitiveUses& uses);

/// St Venant-Kirchhoff model: removes the tetrahedra `removed` (indices in removal order, as
/// topology/TopologyChange.h gives them, each slot receiving the last tetrahedron) of rest
/// shapes `shapes`, subtracting their terms from their vertices, edges and triangles; drops the
/// edges and triangles left unused; zeroes `freedPoints` exactly. `uses` mirrors the model's
/// edges and triangles.
void removeFromStVKTensorMass(std::span<const Index> removed,
                              std::span<const fem::TetrahedronShape> shapes,
                              const fem::LameParameters& lame, std::span<const Index> freedPoints,
                              StVKTensorMass& model, PrimitiveUses& uses);

}  // namespace stroma::tensormass
