// SPDX-License-Identifier: MIT
// SOFA's visual helpers that are not surfaces: VisualGrid, LineAxis (world lines) and
// OglLabel (text on the screen), read by their Data names.
#pragma once

#include "core/Types.h"

namespace stroma {
class Base;
}

namespace stroma::rendering {

/// A VisualGrid (`size`, `nbSubdiv`, `plane` x, y or z: the axis the grid is normal to,
/// `color`, `thickness`) centred on the origin, or a LineAxis (`size`, `axis` letters,
/// `thickness`: x red, y green, z blue, from -size/2 to size/2), in world coordinates with the
/// camera's matrices loaded. Returns the number of lines drawn (0 for other components).
std::size_t drawWorldDecoration(const Base& object);

/// An OglLabel's text (`prefix` `label` `suffix`) at its pixel (`x`, `y`) in our font, about
/// `fontsize` pixels high, in its `color` or, with `selectContrastingColor` or no color, black
/// or white against `background`. Returns false for other components.
bool drawScreenLabel(const Base& object, const Vec4d& background, int width, int height);

}  // namespace stroma::rendering
