// SPDX-License-Identifier: MIT
#include "stroma/rendering/SceneBounds.h"

#include <vector>

#include "SceneReading.h"
#include "core/BaseState.h"
#include "core/Node.h"
#include "simulation/VisualModel.h"

namespace stroma::rendering {

Aabb sceneBounds(const Node& root) {
  Aabb box;
  std::vector<double> coords;
  forEachObject(root, [&](Base& object) {
    if (const auto* state = dynamic_cast<const BaseState*>(&object)) {
      const int dim = state->coordDimension();
      if (dim < 3) return;  // 1D and 2D states have no place in space to fit
      state->copyPositions(coords);
      for (std::size_t i = 0; i + 3 <= coords.size(); i += static_cast<std::size_t>(dim)) {
        const Vec3d p(coords[i], coords[i + 1], coords[i + 2]);
        if (p.allFinite()) box.expand(p);
      }
    } else if (const auto* visual = dynamic_cast<const VisualModel*>(&object)) {
      if (const VisualSurface* surface = visual->surface())
        for (const Vec3d& p : surface->positions)
          if (p.allFinite()) box.expand(p);
    }
  });
  return box;
}

}  // namespace stroma::rendering
