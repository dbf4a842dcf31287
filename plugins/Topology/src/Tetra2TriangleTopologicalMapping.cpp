// SPDX-License-Identifier: MIT
#include "Tetra2TriangleTopologicalMapping.h"

#include "TopologyContainer.h"

namespace stroma {

void Tetra2TriangleTopologicalMapping::init() {
  if (!findTopologies(kinds::triangles, "triangles", "TriangleSetTopologyContainer")) {
    setInvalid();
    return;
  }
  std::vector<Triangle> triangles;
  if (!d_noInitialTriangles.value()) {
    if (input()->tetrahedra().empty())
      msgWarning("the input " + input()->path() + " has no tetrahedra: no triangles are made",
                 "input");
    triangles = input()->boundaryTriangles();
    if (d_flipNormals.value())
      for (Triangle& t : triangles) std::swap(t[1], t[2]);
  }
  setOutput(output()->d_triangles, std::move(triangles));
}

}  // namespace stroma
