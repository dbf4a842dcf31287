// SPDX-License-Identifier: MIT
// The color bar of a color map, drawn in screen space at the right edge.
#pragma once

#include <string>

#include "stroma/rendering/ColorMap.h"

namespace stroma::rendering {

/// Where the legend wrote its numbers (top-left pixel of each text, y downwards), for tests
/// that read them back from the picture.
struct LegendPlacement {
  std::string minText, maxText;
  int minX = 0, minY = 0, maxX = 0, maxY = 0;
  int scale = 1;  ///< pixels per font pixel
};

/// Draws a dark panel with the field's name and unit, a vertical color bar (rampColor, min at
/// the bottom) and the numbers min and max (legendNumber) beside its ends.
LegendPlacement drawLegend(ColorMapKind kind, double min, double max, int width, int height);

}  // namespace stroma::rendering
