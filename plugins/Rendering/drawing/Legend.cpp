// SPDX-License-Identifier: MIT
#include "Legend.h"

#include <GL/gl.h>

#include <algorithm>
#include <cctype>

#include "stroma/rendering/BitmapFont.h"

namespace stroma::rendering {

namespace {

void fillRect(double x0, double y0, double x1, double y1, const Vec4d& c) {
  glColor4d(c[0], c[1], c[2], c[3]);
  glBegin(GL_QUADS);
  glVertex2d(x0, y0);
  glVertex2d(x0, y1);
  glVertex2d(x1, y1);
  glVertex2d(x1, y0);
  glEnd();
}

}  // namespace

LegendPlacement drawLegend(ColorMapKind kind, double min, double max, int width, int height) {
  LegendPlacement out;
  out.scale = height >= 400 ? 2 : 1;
  const int s = out.scale;
  out.minText = legendNumber(min);
  out.maxText = legendNumber(max);
  std::string title = std::string(colorMapName(kind)) + " (" + colorMapUnit(kind) + ")";
  // In a small picture the field's name would take a quarter of it: the unit alone then.
  if (textWidth(title, out.scale) > width / 4) title = std::string("(") + colorMapUnit(kind) + ")";
  // Upper case: the font's lower-case 'e' is for exponents only.
  for (char& c : title) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));

  const int margin = 8 * s, gap = 3 * s, barWidth = 10 * s;
  const int barHeight = std::max(2 * height / 5, 4 * textHeight(s));
  const int barRight = width - margin, barLeft = barRight - barWidth;
  const int barTop = (height - barHeight) / 2 + textHeight(s), barBottom = barTop + barHeight;
  const int numbersWidth = std::max(textWidth(out.minText, s), textWidth(out.maxText, s));
  out.maxX = barLeft - gap - textWidth(out.maxText, s);
  out.maxY = barTop;
  out.minX = barLeft - gap - textWidth(out.minText, s);
  out.minY = barBottom - textHeight(s);
  const int titleX = barRight - textWidth(title, s), titleY = barTop - gap - textHeight(s);
  const int panelLeft = std::min(barLeft - gap - numbersWidth, titleX) - gap;

  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glOrtho(0, width, height, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  fillRect(panelLeft, titleY - gap, width - margin + gap, barBottom + gap,
           Vec4d(0.08, 0.08, 0.1, 1));
  // The bar, min at the bottom, in strips whose ends take the ramp's colors.
  constexpr int kStrips = 32;
  glShadeModel(GL_SMOOTH);
  glBegin(GL_QUAD_STRIP);
  for (int k = 0; k <= kStrips; ++k) {
    const double t = static_cast<double>(k) / kStrips;
    const Vec3d c = rampColor(t);
    const double y = barBottom - t * barHeight;
    glColor3d(c[0], c[1], c[2]);
    glVertex2d(barLeft, y);
    glVertex2d(barRight, y);
  }
  glEnd();
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glPopAttrib();

  const Vec4d white(1, 1, 1, 1);
  drawText(title, titleX, titleY, s, white, width, height);
  drawText(out.maxText, out.maxX, out.maxY, s, white, width, height);
  drawText(out.minText, out.minX, out.minY, s, white, width, height);
  return out;
}

}  // namespace stroma::rendering
