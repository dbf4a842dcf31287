// SPDX-License-Identifier: MIT
// A small bitmap font of our own (5 x 7 pixel glyphs) for legends and heads-up text, drawn
// with OpenGL quads in screen space.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "core/Types.h"

namespace stroma::rendering {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = 6;  ///< glyph width plus one column of space

/// The rows of a glyph, top first, bit 4 the leftmost column. Characters: digits, letters
/// (lower case drawn as upper case), space . , - + : / = % ( ) _ ; others give a box.
const std::array<std::uint8_t, kGlyphHeight>& glyphRows(char c);
/// Whether the font has a glyph of its own for `c` (not the box).
bool hasGlyph(char c);

/// Width and height in pixels of `text` drawn at `scale` (pixels per font pixel).
int textWidth(std::string_view text, int scale);
inline int textHeight(int scale) { return kGlyphHeight * scale; }

/// Draws `text` with its top-left corner at pixel (x, y) (y downwards from the top) of a
/// width x height viewport. Sets its own orthographic matrices and restores them after;
/// lighting, texturing and depth testing are off while it draws.
void drawText(std::string_view text, int x, int y, int scale, const Vec4d& color, int width,
              int height);

}  // namespace stroma::rendering
