// SPDX-License-Identifier: MIT
#pragma once

#include "TopologicalMapping.h"

namespace stroma {

/// Splits the hexahedra of the input into tetrahedra for the output (HexahedronSplit.h): six
/// per hexahedron as SOFA does, or five. Every tetrahedron made from a positive hexahedron is
/// positive, and neighbouring hexahedra share their face diagonals (a conforming mesh).
class Hexa2TetraTopologicalMapping final : public TopologicalMapping {
 public:
  Data<bool> d_swapping{this, "swapping", false,
                        "Six-split: mirror every other hexahedron along each grid axis, so that "
                        "the tetrahedra have no preferred direction (needs hexahedra numbered "
                        "as a regular grid)."};
  Data<int> d_tetrahedraPerHexahedron{
      this,
      "tetrahedraPerHexahedron",
      6,
      "6 (SOFA's split, around the 0-6 diagonal) or 5 (a central tetrahedron and four corners, "
      "alternating between neighbours).",
      {.min = 5.0, .max = 6.0}};

  void init() override;
};

}  // namespace stroma
