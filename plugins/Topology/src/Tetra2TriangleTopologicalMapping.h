// SPDX-License-Identifier: MIT
#pragma once

#include "TopologicalMapping.h"

namespace stroma {

/// The boundary of the input's tetrahedra: the triangles that belong to one tetrahedron,
/// oriented outwards (for positive tetrahedra), in order of first appearance.
class Tetra2TriangleTopologicalMapping final : public TopologicalMapping {
 public:
  Data<bool> d_flipNormals{this, "flipNormals", false,
                           "Orient the triangles inwards instead of outwards."};
  Data<bool> d_noNewTriangles{this, "noNewTriangles", false,
                              "SOFA option for topology changes, accepted: Stroma's topologies "
                              "do not change at run time."};
  Data<bool> d_noInitialTriangles{this, "noInitialTriangles", false,
                                  "Leave the output without triangles at init."};
  void init() override;
};

}  // namespace stroma
