// SPDX-License-Identifier: MIT
// Topology: the interface of every mesh container (MeshTopology, the *SetTopologyContainer
// components, RegularGridTopology). It holds the element lists under SOFA's names and gives the
// adjacency that components need, computed on first use and cached.
//
// Components find their topology in their node (`node()->get<Topology>()`) or by a link, then
// read the lists:
//
//   const Topology* topology = node()->get<Topology>();
//   for (const Tetrahedron& t : topology->tetrahedra()) ...
//   const auto& faces = topology->tetrahedronFaces();   // cached until the elements change
//
// Vertex orders and orientation: TopologyTypes.h. Adjacency kernels: MeshAdjacency.h.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/Base.h"
#include "core/Link.h"
#include "core/Types.h"
#include "topology/MeshAdjacency.h"
#include "topology/SparseGridLevels.h"
#include "topology/TopologyChange.h"
#include "topology/TopologyTypes.h"

namespace stroma {

class Topology : public Base {
 public:
  Topology();
  ~Topology() override;

  Data<std::vector<Vec3d>> d_position{this,
                                      "position",
                                      {},
                                      "Points of the mesh (nbPoints x 3); may be empty when a "
                                      "mechanical state holds the points.",
                                      {.unit = "m"}};
  Data<std::vector<Edge>> d_edges{this, "edges", {}, "Edges (nbEdges x 2 point indices)."};
  Data<std::vector<Triangle>> d_triangles{this,
                                          "triangles",
                                          {},
                                          "Triangles (nbTriangles x 3 point indices), oriented "
                                          "by the right-hand rule."};
  Data<std::vector<Quad>> d_quads{
      this, "quads", {}, "Quads (nbQuads x 4 point indices), in order around the quad."};
  Data<std::vector<Tetrahedron>> d_tetrahedra{
      this,
      "tetrahedra",
      {},
      "Tetrahedra (nbTetrahedra x 4 point indices); (a,b,c,d) is positive when "
      "(b-a).((c-a)x(d-a)) > 0."};
  Data<std::vector<Hexahedron>> d_hexahedra{
      this,
      "hexahedra",
      {},
      "Hexahedra (nbHexahedra x 8 point indices): bottom face 0-3 counterclockwise seen from "
      "above, top face 4-7 above it."};

  // --- Element lists, as given by the scene, a loader or a topological mapping ---------------
  const std::vector<Vec3d>& positions() const { return d_position.value(); }
  const std::vector<Edge>& edges() const { return d_edges.value(); }
  const std::vector<Triangle>& triangles() const { return d_triangles.value(); }
  const std::vector<Quad>& quads() const { return d_quads.value(); }
  const std::vector<Tetrahedron>& tetrahedra() const { return d_tetrahedra.value(); }
  const std::vector<Hexahedron>& hexahedra() const { return d_hexahedra.value(); }

  // --- Sparse grids (SparseGridTopology; null/empty for other topologies) -----------------
  /// The grid whose hexahedra this topology holds: box, cells, types, filled fractions.
  virtual const sparsegrid::SparseGrid* sparseGrid() const { return nullptr; }
  /// Its virtual finer levels (`nbVirtualFinerLevels`), finest first, each with the children of
  /// the next coarser level's cells (the last one's parents are sparseGrid()'s cells).
  virtual std::span<const sparsegrid::FinerLevel> sparseGridFinerLevels() const { return {}; }

  /// The number of positions; without positions, 1 + the largest index any element uses
  /// (0 for an empty topology).
  std::size_t nbPoints() const;

  /// Incremented whenever an element list changes (read from the Data versions): a component
  /// that keeps something derived from the elements compares it with the value it saw.
  std::uint64_t revision() const;

  // --- Run-time changes (cutting): TopologyChange.h -------------------------------------------

  /// Removes the tetrahedra `indices` (any order, duplicates count once), and the triangles and
  /// edges this topology lists that no remaining tetrahedron uses; points are kept. Elements
  /// are renumbered as SOFA does (the last one moves into each removed slot, TopologyChange.h).
  /// The change is logged under the new revision(). A point left without tetrahedra is free:
  /// the first time that happens a warning says so. Returns false, changing nothing, when an
  /// index is not a tetrahedron's; `error` then says which (for the caller to report).
  bool removeTetrahedra(std::span<const Index> indices, std::string& error);

  /// Removes the triangles `indices` (any order, duplicates count once), and the edges this
  /// topology lists that no remaining triangle uses; points are kept, renumbering as
  /// removeTetrahedra. For a topology of triangles (it must hold no tetrahedra). The change
  /// gets a new revision() but is not logged: changesSince() answers std::nullopt across it,
  /// so the components that follow the topology rebuild from the lists. A point left without
  /// triangles is free (the first time, a warning says so). Returns false, changing nothing,
  /// when an index is not a triangle's; `error` then says which.
  bool removeTriangles(std::span<const Index> indices, std::string& error);

  /// The changes from revision `since` to revision(), oldest first, when every one of them is
  /// logged; std::nullopt when not (the elements were set another way, or the log, which keeps
  /// the last kChangeLogCapacity changes, was trimmed): the caller then rebuilds from the
  /// element lists. The span is valid until the next change.
  std::optional<std::span<const TopologyChange>> changesSince(std::uint64_t since) const;
  static constexpr std::size_t kChangeLogCapacity = 64;

  // --- Adjacency, computed on first use and cached until the elements change -----------------
  // The references stay valid until an element list changes. Safe to call from several
  // threads while the elements do not change.

  const ElementEdges<3>& triangleEdges() const;
  const ElementEdges<4>& quadEdges() const;
  const ElementEdges<6>& tetrahedronEdges() const;
  const ElementEdges<12>& hexahedronEdges() const;
  /// Unique triangles of the tetrahedra, with the tetrahedra around each.
  const TetrahedronFaces& tetrahedronFaces() const;
  /// Triangles of the tetrahedra that belong to one tetrahedron only, oriented outwards.
  const std::vector<Triangle>& boundaryTriangles() const;
  /// Unique quads of the hexahedra, with the hexahedra around each.
  const HexahedronFaces& hexahedronFaces() const;
  /// Quads of the hexahedra that belong to one hexahedron only, oriented outwards.
  const std::vector<Quad>& boundaryQuads() const;
  /// Every edge: the given edges, then those of the elements not already listed.
  const std::vector<Edge>& allEdges() const;
  /// For each point (nbPoints()), the tetrahedra using it, in increasing order.
  const AdjacencyList& tetrahedraAroundVertex() const;
  /// For each point (nbPoints()), the hexahedra using it, in increasing order.
  const AdjacencyList& hexahedraAroundVertex() const;
  /// For each point (nbPoints()), the edges of allEdges() using it, in increasing order.
  const AdjacencyList& edgesAroundVertex() const;

 protected:
  /// Checks the elements and reports each problem on this component: indices out of range of
  /// the points (error), degenerate tetrahedra and hexahedra (error), inverted ones (warning).
  /// The geometric checks need positions. Returns false when an error was reported.
  bool checkElements();

 private:
  struct Cache;
  /// Drops the cache when an element list changed. Called with m_mutex held.
  void refresh() const;

  mutable std::mutex m_mutex;
  mutable std::unique_ptr<Cache> m_cache;
  std::vector<TopologyChange> m_changes;  ///< the last changes, oldest first
  bool m_reportedFreedPoints = false;
};

/// The tetrahedral topology a force field works on: the link when given (an error if it has no
/// tetrahedra), else, from the owner's node up, the last topology of the first node that holds
/// tetrahedra. Errors go to `owner`, field "topology"; nullptr after one.
const Topology* findTetrahedralTopology(Base& owner, const Link<Topology>& link);

}  // namespace stroma
