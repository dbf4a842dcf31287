// SPDX-License-Identifier: MIT
#include "Hexa2QuadTopologicalMapping.h"

#include "TopologyContainer.h"

namespace stroma {

void Hexa2QuadTopologicalMapping::init() {
  if (!findTopologies(kinds::quads, "quads", "QuadSetTopologyContainer")) {
    setInvalid();
    return;
  }
  if (input()->hexahedra().empty())
    msgWarning("the input " + input()->path() + " has no hexahedra: no quads are made", "input");
  std::vector<Quad> quads = input()->boundaryQuads();
  if (d_flipNormals.value())
    for (Quad& q : quads) std::swap(q[1], q[3]);
  setOutput(output()->d_quads, std::move(quads));
}

}  // namespace stroma
