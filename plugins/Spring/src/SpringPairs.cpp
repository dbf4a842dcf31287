// SPDX-License-Identifier: MIT
#include "SpringPairs.h"

#include <unordered_set>

#include "core/Node.h"

namespace stroma {

namespace {

// For each unique edge, the first two (element, local edge) that have it, and how many more.
template <std::size_t EdgesPerElement>
struct EdgeSides {
  std::vector<std::array<std::uint32_t, 2>> element, local;
  std::vector<std::uint8_t> count;

  explicit EdgeSides(const ElementEdges<EdgesPerElement>& edges)
      : element(edges.edges.size()), local(edges.edges.size()), count(edges.edges.size(), 0) {
    for (std::size_t e = 0; e < edges.edgesInElement.size(); ++e)
      for (std::size_t k = 0; k < EdgesPerElement; ++k) {
        const Index edge = edges.edgesInElement[e][k];
        if (count[edge] < 2) {
          element[edge][count[edge]] = static_cast<std::uint32_t>(e);
          local[edge][count[edge]] = static_cast<std::uint32_t>(k);
        }
        if (count[edge] < 255) ++count[edge];
      }
  }
  std::size_t nonManifold() const {
    std::size_t n = 0;
    for (std::uint8_t c : count) n += c > 2;
    return n;
  }
};

}  // namespace

TriangleHinges findTriangleHinges(std::span<const Triangle> triangles,
                                  const ElementEdges<3>& edges) {
  const EdgeSides<3> sides(edges);
  TriangleHinges result;
  result.nonManifoldEdges = sides.nonManifold();
  for (std::size_t e = 0; e < edges.edges.size(); ++e) {
    if (sides.count[e] < 2) continue;
    // Edge k of a triangle is opposite its vertex k (kTriangleEdges).
    const Triangle& t1 = triangles[sides.element[e][0]];
    const Triangle& t2 = triangles[sides.element[e][1]];
    const std::uint32_t k1 = sides.local[e][0], k2 = sides.local[e][1];
    result.hinges.push_back({t1[(k1 + 1) % 3], t1[k1], t1[(k1 + 2) % 3], t2[k2]});
  }
  return result;
}

BendingPairs findQuadBendingPairs(std::span<const Quad> quads, const ElementEdges<4>& edges,
                                  bool once) {
  const EdgeSides<4> sides(edges);
  BendingPairs result;
  result.nonManifoldEdges = sides.nonManifold();
  std::unordered_set<std::uint64_t> made;
  auto add = [&](Index p, Index q) {
    if (p == q) return;
    const std::uint64_t key = (std::uint64_t{std::min(p, q)} << 32) | std::max(p, q);
    if (once && !made.insert(key).second) return;
    result.pairs.push_back({p, q});
  };
  for (std::size_t e = 0; e < edges.edges.size(); ++e) {
    if (sides.count[e] < 2) continue;
    // Edge k of a quad joins its vertices k and k + 1 (kQuadEdges): outside the edge, vertex
    // k + 3 is next to vertex k and vertex k + 2 next to vertex k + 1.
    const Quad& q1 = quads[sides.element[e][0]];
    const Quad& q2 = quads[sides.element[e][1]];
    const std::uint32_t k1 = sides.local[e][0], k2 = sides.local[e][1];
    const Index a = q1[k1];
    const Index nextToA1 = q1[(k1 + 3) % 4], nextToB1 = q1[(k1 + 2) % 4];
    const bool sameWay = q2[k2] == a;
    const Index nextToA2 = sameWay ? q2[(k2 + 3) % 4] : q2[(k2 + 2) % 4];
    const Index nextToB2 = sameWay ? q2[(k2 + 2) % 4] : q2[(k2 + 3) % 4];
    add(nextToA1, nextToA2);
    add(nextToB1, nextToB2);
  }
  return result;
}

GridPairs findGridPairs(const Topology& topology) {
  GridPairs result;
  auto addDiagonals = [&](std::span<const Quad> faces) {
    for (const Quad& q : faces) {
      result.faceDiagonals.push_back({q[0], q[2]});
      result.faceDiagonals.push_back({q[1], q[3]});
    }
  };
  if (!topology.hexahedra().empty()) {
    result.lines = topology.hexahedronEdges().edges;
    addDiagonals(topology.hexahedronFaces().faces);
    // Bottom face 0-3, top face 4-7 above it: vertex i of the bottom faces vertex (i+2)%4 + 4.
    for (const Hexahedron& h : topology.hexahedra())
      for (int i = 0; i < 4; ++i) result.cellDiagonals.push_back({h[i], h[(i + 2) % 4 + 4]});
  } else if (!topology.quads().empty()) {
    result.lines = topology.quadEdges().edges;
    addDiagonals(topology.quads());
  } else {
    result.lines = topology.allEdges();
  }
  return result;
}

const Topology* findSpringTopology(Base& owner, const Link<Topology>& link,
                                   const std::string& needs) {
  const Topology* topology =
      link ? link.get() : (owner.node() ? owner.node()->template getUp<Topology>() : nullptr);
  if (!topology)
    owner.msgError("needs a topology with " + needs +
                       " (MeshTopology, a *SetTopologyContainer, RegularGridTopology, ...) in its "
                       "node or above, or a 'topology' link",
                   "topology");
  return topology;
}

}  // namespace stroma
