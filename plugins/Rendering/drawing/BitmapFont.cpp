// SPDX-License-Identifier: MIT
#include "stroma/rendering/BitmapFont.h"

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

}  // namespace stroma::rendering
