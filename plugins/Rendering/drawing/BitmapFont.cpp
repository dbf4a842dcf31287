// SPDX-License-Identifier: MIT
#include "stroma/rendering/BitmapFont.h"

#include <GL/gl.h>

#include <cctype>
#include <map>

namespace stroma::rendering {

namespace {

struct GlyphText {
  char c;
  const char* rows[kGlyphHeight];
};

constexpr GlyphText kGlyphs[] = {
#include "glyphs.inc"
};

constexpr GlyphText kBox = {0, {"#####", "#...#", "#...#", "#...#", "#...#", "#...#", "#####"}};

std::array<std::uint8_t, kGlyphHeight> toBits(const GlyphText& g) {
  std::array<std::uint8_t, kGlyphHeight> bits{};
  for (int r = 0; r < kGlyphHeight; ++r)
    for (int c = 0; c < kGlyphWidth; ++c)
      if (g.rows[r][c] == '#') bits[r] |= static_cast<std::uint8_t>(1u << (kGlyphWidth - 1 - c));
  return bits;
}

const std::map<char, std::array<std::uint8_t, kGlyphHeight>>& table() {
  static const auto glyphs = [] {
    std::map<char, std::array<std::uint8_t, kGlyphHeight>> out;
    for (const GlyphText& g : kGlyphs) out[g.c] = toBits(g);
    return out;
  }();
  return glyphs;
}

/// Lower case letters are drawn as upper case, except 'e', which numbers use (1.5e+04).
char normalized(char c) {
  if (c == 'e') return c;
  return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}

}  // namespace

bool hasGlyph(char c) { return table().count(normalized(c)) > 0; }

const std::array<std::uint8_t, kGlyphHeight>& glyphRows(char c) {
  static const auto box = toBits(kBox);
  auto it = table().find(normalized(c));
  return it == table().end() ? box : it->second;
}

int textWidth(std::string_view text, int scale) {
  if (text.empty()) return 0;
  return (static_cast<int>(text.size()) * kGlyphAdvance - 1) * scale;
}

void drawText(std::string_view text, int x, int y, int scale, const Vec4d& color, int width,
              int height) {
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glOrtho(0, width, height, 0, -1, 1);  // pixels, y downwards
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
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
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glPopAttrib();
}

}  // namespace stroma::rendering
