// SPDX-License-Identifier: MIT
// SOFA's family of set containers, one element kind each with the kinds below it. They differ
// only in what they keep (TopologyContainer does the work), so they share this file.
#pragma once

#include "TopologyContainer.h"

namespace stroma {

/// Points only.
class PointSetTopologyContainer final : public TopologyContainer {
 public:
  Data<bool> d_checkTopology{this, "checkTopology", false,
                             "SOFA option; Stroma always checks the elements at init."};
  PointSetTopologyContainer() : TopologyContainer(0, true) {}
};

/// Edges.
class EdgeSetTopologyContainer final : public TopologyContainer {
 public:
  Data<bool> d_checkTopology{this, "checkTopology", false,
                             "SOFA option; Stroma always checks the elements at init."};
  Data<bool> d_checkConnexity{this, "checkConnexity", false,
                              "SOFA option, accepted; Stroma does not check connexity."};
  EdgeSetTopologyContainer() : TopologyContainer(kinds::edges, true) {}
};

/// Triangles and their edges.
class TriangleSetTopologyContainer final : public TopologyContainer {
 public:
  Data<bool> d_checkTopology{this, "checkTopology", false,
                             "SOFA option; Stroma always checks the elements at init."};
  TriangleSetTopologyContainer() : TopologyContainer(kinds::edges | kinds::triangles, true) {}
};

/// Quads and their edges.
class QuadSetTopologyContainer final : public TopologyContainer {
 public:
  Data<bool> d_checkTopology{this, "checkTopology", false,
                             "SOFA option; Stroma always checks the elements at init."};
  QuadSetTopologyContainer() : TopologyContainer(kinds::edges | kinds::quads, true) {}
};

/// Tetrahedra, their triangles and edges.
class TetrahedronSetTopologyContainer final : public TopologyContainer {
 public:
  Data<std::vector<Tetrahedron>> d_tetras{
      this, "tetras", {}, "SOFA's other name for tetrahedra.", {.autoLink = false}};
  Data<bool> d_checkTopology{this, "checkTopology", false,
                             "SOFA option; Stroma always checks the elements at init."};
  Data<bool> d_createTriangleArray{
      this, "createTriangleArray", false,
      "SOFA option; Stroma always creates the triangles of the tetrahedra when none are given."};
  TetrahedronSetTopologyContainer()
      : TopologyContainer(kinds::edges | kinds::triangles | kinds::tetrahedra, true) {}

 protected:
  void adoptAliases() override { adoptAlias(d_tetras, d_tetrahedra); }
};

/// Hexahedra, their quads and edges.
class HexahedronSetTopologyContainer final : public TopologyContainer {
 public:
  Data<std::vector<Hexahedron>> d_hexas{
      this, "hexas", {}, "SOFA's other name for hexahedra.", {.autoLink = false}};
  Data<bool> d_checkTopology{this, "checkTopology", false,
                             "SOFA option; Stroma always checks the elements at init."};
  Data<bool> d_createQuadArray{
      this, "createQuadArray", false,
      "SOFA option; Stroma always creates the quads of the hexahedra when none are given."};
  HexahedronSetTopologyContainer()
      : TopologyContainer(kinds::edges | kinds::quads | kinds::hexahedra, true) {}

 protected:
  void adoptAliases() override { adoptAlias(d_hexas, d_hexahedra); }
};

}  // namespace stroma
