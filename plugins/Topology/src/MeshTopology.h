// SPDX-License-Identifier: MIT
#pragma once

#include <array>

#include "TopologyContainer.h"

namespace stroma {

/// A mesh of any elements, kept as given (SOFA's MeshTopology): points, edges, triangles,
/// quads, tetrahedra and hexahedra, from the scene, `src="@loader"` or `filename`.
class MeshTopology final : public TopologyContainer {
 public:
  Data<std::vector<Edge>> d_lines{
      this, "lines", {}, "SOFA's other name for edges.", {.autoLink = false}};
  Data<std::vector<Tetrahedron>> d_tetras{
      this, "tetras", {}, "SOFA's other name for tetrahedra.", {.autoLink = false}};
  Data<std::vector<Hexahedron>> d_hexas{
      this, "hexas", {}, "SOFA's other name for hexahedra.", {.autoLink = false}};
  Data<std::vector<std::array<Index, 5>>> d_pyramids{
      this, "pyramids", {}, "Pyramids (n x 5 point indices); kept, not used by Stroma components."};
  Data<std::vector<std::array<Index, 6>>> d_prisms{
      this, "prisms", {}, "Prisms (n x 6 point indices); kept, not used by Stroma components."};
  Data<bool> d_drawEdges{this, "drawEdges", false, "Draw the edges (viewers only)."};
  Data<bool> d_drawTriangles{this, "drawTriangles", false, "Draw the triangles (viewers only)."};
  Data<bool> d_drawQuads{this, "drawQuads", false, "Draw the quads (viewers only)."};
  Data<bool> d_drawTetrahedra{this, "drawTetrahedra", false, "Draw the tetrahedra (viewers only)."};
  Data<bool> d_drawHexahedra{this, "drawHexahedra", false, "Draw the hexahedra (viewers only)."};

  MeshTopology() : TopologyContainer(kinds::all, false) {}

 protected:
  void adoptAliases() override {
    adoptAlias(d_lines, d_edges);
    adoptAlias(d_tetras, d_tetrahedra);
    adoptAlias(d_hexas, d_hexahedra);
  }
};

}  // namespace stroma
