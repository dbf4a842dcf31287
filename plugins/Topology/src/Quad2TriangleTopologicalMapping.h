// SPDX-License-Identifier: MIT
#pragma once

#include "TopologicalMapping.h"

namespace stroma {

/// Splits each quad (a, b, c, d) of the input into the triangles (a, b, c) and (a, c, d), which
/// keep the quad's orientation.
class Quad2TriangleTopologicalMapping final : public TopologicalMapping {
 public:
  void init() override;
};

/// The border of the input's triangles: the edges that belong to one triangle, oriented as in
/// their triangle.
class Triangle2EdgeTopologicalMapping final : public TopologicalMapping {
 public:
  void init() override;
};

}  // namespace stroma
