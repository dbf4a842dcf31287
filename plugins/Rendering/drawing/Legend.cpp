// SPDX-License-Identifier: MIT
#include "Legend.h"

#include <GL/gl.h>

#include <algorithm>
#include <cctype>

#include "GlPrimitives.h"
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
  out.minText = legendNumber(min);
  out.maxText = legendNumber(max);
  const int chars = static_cast<int>(std::max(out.minText.size(), out.maxText.size()));
  const LegendLayout l = layOutLegend(kind, chars, width, height);
  const int s = out.scale = l.scale;
  out.maxX = l.barLeft - l.gap - textWidth(out.maxText, s);
  out.maxY = l.barTop;
  out.minX = l.barLeft - l.gap - textWidth(out.minText, s);
  out.minY = l.barBottom - textHeight(s);
  const int barLeft = l.barLeft, barRight = l.barRight, barTop = l.barTop, barBottom = l.barBottom;
  const int barHeight = barBottom - barTop;

  {
    const PixelSpace pixels(width, height);
    fillRect(l.panelLeft, l.panelTop, l.panelRight, l.panelBottom, Vec4d(0.08, 0.08, 0.1, 1));
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
  }

  const Vec4d white(1, 1, 1, 1);
  drawText(l.title, l.titleX, l.titleY, s, white, width, height);
  drawText(out.maxText, out.maxX, out.maxY, s, white, width, height);
  drawText(out.minText, out.minX, out.minY, s, white, width, height);
  return out;
}

}  // namespace stroma::rendering
