// SPDX-License-Identifier: MIT
// Which pairs of points the spring families on meshes join, read from element lists, and the
// springs made on such pairs at rest positions. Free of components: TriangularBendingSprings,
// QuadularBendingSprings, QuadBendingSprings and RegularGridSpringForceField wire them to their
// Data, the spring law is SpringKernel.h.
//
// Bending pairs (the springs resist folding along an edge because folding shortens them):
//   triangles: for each edge shared by two triangles, the two vertices opposite the edge;
//   quads:     for each edge (a, b) shared by two quads, the vertex next to a outside the edge in
//              the first quad with the one in the second (a spring across a), the same for b.
// An edge of more than two elements (not a manifold) uses its first two, as SOFA does; the count
// of such edges is returned for the component to report.
//
// Grid pairs (RegularGridSpringForceField): the lines of the grid (the edges of its cells), both
// diagonals of each face, the four main diagonals of each cell. A grid of hexahedra takes its
// edges and faces from them; a flat grid (quads only) its lines from the quads; a line of points
// its edges.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "LinearSpring.h"
#include "core/Base.h"
#include "core/Link.h"
#include "core/Types.h"
#include "topology/Topology.h"

namespace stroma {

/// Two triangles sharing the edge (a, c): `b` is opposite the edge in the first one, `d` in the
/// second one, so that (a, b, c, d) goes around the pair.
struct TriangleHinge {
  Index a, b, c, d;
};

struct TriangleHinges {
  std::vector<TriangleHinge> hinges;
  std::size_t nonManifoldEdges = 0;  ///< edges of more than two triangles (first two used)
};

/// One hinge per edge shared by two triangles, in the order of the edges (`edges` are the
/// triangles' edges, Topology::triangleEdges()).
TriangleHinges findTriangleHinges(std::span<const Triangle> triangles,
                                  const ElementEdges<3>& edges);

struct BendingPairs {
  std::vector<Edge> pairs;
  std::size_t nonManifoldEdges = 0;  ///< edges of more than two elements (first two used)
};

/// The two pairs across each edge shared by two quads (`edges`: Topology::quadEdges()). With
/// `once`, a pair that several edges give is listed once (QuadBendingSprings); without, once per
/// edge (QuadularBendingSprings: a pair inside a grid is then given by the two edges it crosses).
BendingPairs findQuadBendingPairs(std::span<const Quad> quads, const ElementEdges<4>& edges,
                                  bool once);

struct GridPairs {
  std::vector<Edge> lines;          ///< edges of the grid
  std::vector<Edge> faceDiagonals;  ///< 2 per face (quad)
  std::vector<Edge> cellDiagonals;  ///< 4 per cell (hexahedron)
};

/// The pairs of a grid of hexahedra, else of quads, else of edges (see the file comment).
GridPairs findGridPairs(const Topology& topology);

/// The topology of `link` when given, else the nearest one from the owner's node up. Reports an
/// error (field "topology") naming what it needs, and returns nullptr, when there is none.
const Topology* findSpringTopology(Base& owner, const Link<Topology>& link,
                                   const std::string& needs);

/// Appends one spring per pair, rest length the distance at `rest`. With `perLength`, ks and kd
/// are divided by the rest length (a spring of zero length keeps them). Returns how many pairs
/// were skipped for using a point past `rest` (the caller reports them).
template <int N>
std::size_t appendSprings(std::span<const Edge> pairs, const std::vector<Vec<N>>& rest, double ks,
                          double kd, bool perLength, std::vector<LinearSpring>& springs) {
  std::size_t outOfRange = 0;
  for (const Edge& p : pairs) {
    if (p[0] >= rest.size() || p[1] >= rest.size()) {
      ++outOfRange;
      continue;
    }
    if (p[0] == p[1]) continue;
    const double length = (rest[p[1]] - rest[p[0]]).norm();
    const double scale = perLength && length > 1e-12 ? 1 / length : 1.0;
    springs.push_back({p[0], p[1], ks * scale, kd * scale, length});
  }
  return outOfRange;
}

}  // namespace stroma
