// SPDX-License-Identifier: MIT
#include "SceneDecorations.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "GlPrimitives.h"
#include "SceneReading.h"
#include "core/Base.h"
#include "stroma/rendering/BitmapFont.h"

namespace stroma::rendering {

namespace {

double number(const Base& object, const char* name, double fallback) {
  std::vector<double> v;
  return readNumbers(object, name, v) && v.size() == 1 && std::isfinite(v[0]) ? v[0] : fallback;
}

void setLineWidth(const Base& object) {
  glLineWidth(static_cast<GLfloat>(std::clamp(number(object, "thickness", 1.0), 1.0, 10.0)));
}

std::size_t drawGrid(const Base& grid) {
  const double size = number(grid, "size", 10.0);
  const int cells = static_cast<int>(std::clamp(number(grid, "nbSubdiv", 16.0), 1.0, 1000.0));
  const std::string plane = readText(grid, "plane");
  // The grid's two in-plane axes: the others than its normal.
  const int normal = plane == "x" ? 0 : plane == "y" ? 1 : 2;
  const int u = (normal + 1) % 3, v = (normal + 2) % 3;
  Vec4d color(0.34, 0.34, 0.34, 1.0);
  parseColor(readText(grid, "color"), color);
  glColor4d(color[0], color[1], color[2], color[3]);
  setLineWidth(grid);
  std::size_t lines = 0;
  for (int i = 0; i <= cells; ++i) {
    const double t = -0.5 * size + size * i / cells;
    Vec3d a = Vec3d::Zero(), b = Vec3d::Zero(), c = Vec3d::Zero(), d = Vec3d::Zero();
    a[u] = b[u] = t;
    a[v] = -0.5 * size;
    b[v] = 0.5 * size;
    c[v] = d[v] = t;
    c[u] = -0.5 * size;
    d[u] = 0.5 * size;
    drawSegment(a, b);
    drawSegment(c, d);
    lines += 2;
  }
  glLineWidth(1.0f);
  return lines;
}

std::size_t drawAxes(const Base& axes) {
  const double half = 0.5 * number(axes, "size", 10.0);
  std::string which = readText(axes, "axis");
  if (which.empty()) which = "xyz";
  setLineWidth(axes);
  std::size_t lines = 0;
  for (int k = 0; k < 3; ++k) {
    if (which.find("xyz"[k]) == std::string::npos && which.find("XYZ"[k]) == std::string::npos)
      continue;
    const Vec3d direction = Vec3d::Unit(k);
    glColor4d(k == 0, k == 1, k == 2, 1.0);
    drawSegment(-half * direction, half * direction);
    ++lines;
  }
  glLineWidth(1.0f);
  return lines;
}

}  // namespace

std::size_t drawWorldDecoration(const Base& object) {
  const std::string& kind = object.className();
  if (kind != "VisualGrid" && kind != "LineAxis") return 0;
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LINE_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  const std::size_t lines = kind == "VisualGrid" ? drawGrid(object) : drawAxes(object);
  glPopAttrib();
  return lines;
}

bool drawScreenLabel(const Base& object, const Vec4d& background, int width, int height) {
  if (object.className() != "OglLabel") return false;
  const std::string text =
      readText(object, "prefix") + readText(object, "label") + readText(object, "suffix");
  if (text.empty()) return true;
  Vec4d color(1, 1, 1, 1);
  const std::string given = readText(object, "color");
  const std::string contrast = readText(object, "selectContrastingColor");
  if (given.empty() || contrast == "1" || contrast == "true" || !parseColor(given, color)) {
    // Rec. 601 luma of the background: dark backgrounds get white text.
    const double luma = 0.299 * background[0] + 0.587 * background[1] + 0.114 * background[2];
    color = luma < 0.5 ? Vec4d(1, 1, 1, 1) : Vec4d(0, 0, 0, 1);
  }
  const int scale =
      std::max(1, static_cast<int>(std::lround(number(object, "fontsize", 14) / kGlyphHeight)));
  drawText(text, static_cast<int>(number(object, "x", 10)),
           static_cast<int>(number(object, "y", 10)), scale, color, width, height);
  return true;
}

}  // namespace stroma::rendering
