// SPDX-License-Identifier: MIT
#include "Hexa2TetraTopologicalMapping.h"

#include "HexahedronSplit.h"
#include "TopologyContainer.h"
#include "topology/MeshGeometry.h"

namespace stroma {

void Hexa2TetraTopologicalMapping::init() {
  if (!findTopologies(kinds::tetrahedra, "tetrahedra", "TetrahedronSetTopologyContainer")) {
    setInvalid();
    return;
  }
  const std::vector<Hexahedron>& hexahedra = input()->hexahedra();
  if (hexahedra.empty())
    msgWarning("the input " + input()->path() + " has no hexahedra: no tetrahedra are made",
               "input");
  std::vector<Tetrahedron> tetrahedra;
  if (d_tetrahedraPerHexahedron.value() == 5) {
    FiveSplit split = splitHexahedraInFive(hexahedra);
    if (split.mismatchedFaces > 0)
      msgWarning(std::to_string(split.mismatchedFaces) +
                     " faces between hexahedra cannot get the same diagonal from both sides with "
                     "five tetrahedra per hexahedron: the tetrahedral mesh is not conforming "
                     "there; use tetrahedraPerHexahedron=\"6\"",
                 "tetrahedraPerHexahedron");
    tetrahedra = std::move(split.tetrahedra);
  } else {
    std::vector<std::uint8_t> mirrors;
    if (d_swapping.value()) {
      if (const auto cells = findGridCells(hexahedra))
        mirrors = alternatingMirrors(*cells);
      else if (!hexahedra.empty())
        msgWarning(
            "swapping needs hexahedra numbered as a regular grid (as RegularGridTopology "
            "makes them); these are not, so no hexahedron is mirrored",
            "swapping");
    }
    tetrahedra = splitHexahedraInSix(hexahedra, mirrors);
  }
  // A hexahedron given inverted gives inverted tetrahedra: turn them (the input container has
  // already warned about the hexahedron).
  const std::vector<Vec3d>& points = input()->positions();
  if (!points.empty())
    for (Tetrahedron& t : tetrahedra) {
      bool inRange = true;
      for (Index v : t) inRange &= v < points.size();
      if (inRange && signedVolume(points, t) < 0) std::swap(t[2], t[3]);
    }
  setOutput(output()->d_tetrahedra, std::move(tetrahedra));
}

}  // namespace stroma
