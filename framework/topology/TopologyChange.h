// SPDX-License-Identifier: MIT
// Topological changes: what removing tetrahedra did to the element lists of a topology, so that
// a component that keeps per-element or per-point data can follow at a cost proportional to
// what was removed instead of rebuilding from the whole mesh.
//
// Renumbering (SOFA's): the elements are removed one at a time in decreasing order of their
// index; each removed slot receives the last element of the list, which shrinks by one. A
// component keeping one value per element replays that with applyRemoval() below; `moved` gives
// the net effect (old index -> new index of each kept element that changed place).
//
//   for (const TopologyChange& change : *topology->changesSince(m_revision))
//     applyRemoval(m_perTetrahedron, change.tetrahedra.removed);
//
// Points are never removed: state vectors keep their size, and a point whose last tetrahedron
// went is listed in `freedPoints` (it has no stiffness anymore).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "topology/TopologyTypes.h"

namespace stroma {

/// The removal of some elements of one kind (tetrahedra, triangles or edges).
template <class Element>
struct ElementRemoval {
  /// Indices of the removed elements before the change, in decreasing order: the order in
  /// which they were removed (each index is also its slot at the time it was removed).
  std::vector<Index> removed;
  /// The vertices of each removed element (same order as `removed`).
  std::vector<Element> removedElements;
  /// (old index, new index) of every kept element whose index changed, by increasing old index.
  std::vector<std::pair<Index, Index>> moved;
  /// The number of elements before and after the change.
  std::size_t sizeBefore = 0, sizeAfter = 0;

  bool empty() const { return removed.empty(); }
};

/// One change of a topology (one call of Topology::removeTetrahedra).
struct TopologyChange {
  /// The topology revision this change produced (Topology::revision() right after it).
  std::uint64_t revision = 0;
  ElementRemoval<Tetrahedron> tetrahedra;
  /// Triangles and edges of the removed tetrahedra that belong to no remaining tetrahedron
  /// (only when the topology lists triangles and edges).
  ElementRemoval<Triangle> triangles;
  ElementRemoval<Edge> edges;
  /// Points of the removed tetrahedra that belong to no remaining tetrahedron, increasing.
  std::vector<Index> freedPoints;
};

/// Replays a removal on data kept per element: for each index r of `removed` in order,
/// values[r] takes the last value and the last is dropped. `values` must have the size the
/// element list had before the change.
template <class T>
void applyRemoval(std::vector<T>& values, std::span<const Index> removed) {
  for (Index r : removed) {
    if (static_cast<std::size_t>(r) + 1 != values.size()) values[r] = std::move(values.back());
    values.pop_back();
  }
}

/// Removes the tetrahedra `indices` (any order; duplicates count once) from `tetrahedra`, and
/// from `triangles` and `edges` (when not empty) those of their faces and edges that no remaining
/// tetrahedron uses. Fills `change` (all but `revision`). Returns false, changing nothing, when an
/// index is not that of a tetrahedron; `error` then names the first such index.
/// Cost: linear in the number of elements (one pass to find what remains around the touched
/// points); no allocation proportional to the mesh beyond hash sets of the touched elements.
bool removeTetrahedraFromLists(std::vector<Tetrahedron>& tetrahedra,
                               std::vector<Triangle>& triangles, std::vector<Edge>& edges,
                               std::span<const Index> indices, TopologyChange& change,
                               std::string& error);

/// Removes the triangles `indices` (any order; duplicates count once) from `triangles`, and from
/// `edges` those of their edges that no remaining triangle uses, with the same renumbering as
/// removeTetrahedraFromLists. Fills `change.triangles`, `change.edges` and `change.freedPoints`
/// (the points of the removed triangles that no remaining triangle uses). Returns false,
/// changing nothing, when an index is not that of a triangle; `error` then names the first.
bool removeTrianglesFromLists(std::vector<Triangle>& triangles, std::vector<Edge>& edges,
                              std::span<const Index> indices, TopologyChange& change,
                              std::string& error);

}  // namespace stroma
