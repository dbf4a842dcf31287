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

/// Where everything of the legend goes (pixels, y downwards), for numbers of up to
/// `numbersWidthInChars` characters.
struct LegendLayout {
  int scale, margin, gap;
  std::string title;
  int barLeft, barRight, barTop, barBottom;
  int titleX, titleY;
  int panelLeft, panelTop, panelRight, panelBottom;
};

LegendLayout layOutLegend(ColorMapKind kind, int numbersWidthInChars, int width, int height);

/// Draws a dark panel with the field's name and unit, a vertical color bar (rampColor, min at
/// the bottom) and the numbers min and max (legendNumber) beside its ends.
LegendPlacement drawLegend(ColorMapKind kind, double min, double max, int width, int height);

}  // namespace stroma::rendering
