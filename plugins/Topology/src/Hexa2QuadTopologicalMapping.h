// SPDX-License-Identifier: MIT
#pragma once

#include "TopologicalMapping.h"

namespace stroma {

/// The boundary of the input's hexahedra: the quads that belong to one hexahedron, oriented
/// outwards, in order of first appearance.
class Hexa2QuadTopologicalMapping final : public TopologicalMapping {
 public:
  Data<bool> d_flipNormals{this, "flipNormals", false,
                           "Orient the quads inwards instead of outwards."};
  void init() override;
};

}  // namespace stroma
