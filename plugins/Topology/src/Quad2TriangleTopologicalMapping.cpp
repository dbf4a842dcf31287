// SPDX-License-Identifier: MIT
#include "Quad2TriangleTopologicalMapping.h"

#include "TopologyContainer.h"

namespace stroma {

void Quad2TriangleTopologicalMapping::init() {
  if (!findTopologies(kinds::triangles, "triangles", "TriangleSetTopologyContainer")) {
    setInvalid();
    return;
  }
  if (input()->quads().empty())
    msgWarning("the input " + input()->path() + " has no quads: no triangles are made", "input");
  std::vector<Triangle> triangles;
  triangles.reserve(input()->quads().size() * 2);
  for (const Quad& q : input()->quads()) {
    triangles.push_back({q[0], q[1], q[2]});
    triangles.push_back({q[0], q[2], q[3]});
  }
  setOutput(output()->d_triangles, std::move(triangles));
}

void Triangle2EdgeTopologicalMapping::init() {
  if (!findTopologies(kinds::edges, "edges", "EdgeSetTopologyContainer")) {
    setInvalid();
    return;
  }
  if (input()->triangles().empty())
    msgWarning("the input " + input()->path() + " has no triangles: no edges are made", "input");
  setOutput(output()->d_edges, computeBoundaryEdges(input()->triangles()));
}

}  // namespace stroma
