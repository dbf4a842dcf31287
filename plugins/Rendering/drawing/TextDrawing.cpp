// SPDX-License-Identifier: MIT
// BitmapFont's drawing, apart from its glyph table so that what only reads glyphs (tests,
// layout) links no OpenGL.
#include <GL/gl.h>

#include "GlPrimitives.h"
#include "stroma/rendering/BitmapFont.h"

namespace stroma::rendering {

void drawText(std::string_view text, int x, int y, int scale, const Vec4d& color, int width,
              int height) {
  const PixelSpace pixels(width, height);
  glColor4d(color[0], color[1], color[2], color[3]);
  glBegin(GL_QUADS);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto& rows = glyphRows(text[i]);
    const int left = x + static_cast<int>(i) * kGlyphAdvance * scale;
    for (int r = 0; r < kGlyphHeight; ++r)
      for (int c = 0; c < kGlyphWidth; ++c) {
        if (!(rows[r] >> (kGlyphWidth - 1 - c) & 1u)) continue;
        const double px = left + c * scale, py = y + r * scale;
        glVertex2d(px, py);
        glVertex2d(px, py + scale);
        glVertex2d(px + scale, py + scale);
        glVertex2d(px + scale, py);
      }
  }
  glEnd();
}

}  // namespace stroma::rendering
