// SPDX-License-Identifier: MIT
// The legend's layout, apart from its drawing so that what only measures it links no OpenGL.
#include <algorithm>
#include <cctype>

#include "Legend.h"
#include "stroma/rendering/BitmapFont.h"
#include "stroma/rendering/SceneDrawer.h"

namespace stroma::rendering {

LegendLayout layOutLegend(ColorMapKind kind, int numbersWidthInChars, int width, int height) {
  LegendLayout l;
  l.scale = height >= 400 ? 2 : 1;
  const int s = l.scale;
  l.title = std::string(colorMapName(kind)) + " (" + colorMapUnit(kind) + ")";
  // In a small picture the field's name would take a quarter of it: the unit alone then.
  if (textWidth(l.title, s) > width / 4) l.title = std::string("(") + colorMapUnit(kind) + ")";
  // Upper case: the font's lower-case 'e' is for exponents only.
  for (char& c : l.title) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  l.margin = 8 * s;
  l.gap = 3 * s;
  const int barHeight = std::max(2 * height / 5, 4 * textHeight(s));
  l.barRight = width - l.margin;
  l.barLeft = l.barRight - 10 * s;
  l.barTop = (height - barHeight) / 2 + textHeight(s);
  l.barBottom = l.barTop + barHeight;
  l.titleX = l.barRight - textWidth(l.title, s);
  l.titleY = l.barTop - l.gap - textHeight(s);
  const int numbersWidth = textWidth(std::string(std::size_t(numbersWidthInChars), '0'), s);
  l.panelLeft = std::min(l.barLeft - l.gap - numbersWidth, l.titleX) - l.gap;
  l.panelTop = l.titleY - l.gap;
  l.panelRight = width - l.margin + l.gap;
  l.panelBottom = l.barBottom + l.gap;
  return l;
}

int legendWidth(ColorMapKind kind, int width, int height) {
  // Numbers as long as %.3g writes them: "-1.23e+04".
  return width - layOutLegend(kind, 9, width, height).panelLeft;
}

}  // namespace stroma::rendering
