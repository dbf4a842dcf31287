// SPDX-License-Identifier: MIT
// The box that holds what a scene draws, for fitting a camera.
#pragma once

#include "collision/Aabb.h"

namespace stroma {
class Node;
}

namespace stroma::rendering {

/// The box around every mechanical state's positions (the first three numbers of each
/// coordinate: frames count by their origins) and every visual surface's positions, under
/// `root`. Visual surfaces are read as they are (call VisualModel::updateVisual() before when
/// they must be current). Empty when the scene has neither.
Aabb sceneBounds(const Node& root);

}  // namespace stroma::rendering
