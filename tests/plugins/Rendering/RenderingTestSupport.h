// SPDX-License-Identifier: MIT
// What the rendering tests share: comparing pictures with a tolerance, and reading back the
// text that our bitmap font wrote into a picture.
#pragma once

#include <cstdlib>
#include <string>

#include "stroma/rendering/BitmapFont.h"
#include "stroma/rendering/PngImage.h"

namespace stroma::test {

/// Per-pixel tolerance of picture comparisons: a pixel matches when no channel differs by
/// more than kChannelTolerance (of 255), and two pictures match when at least
/// kMatchingFraction of their pixels do. OSMesa's rasterizer (llvmpipe, softpipe) gives the
/// same bits on one machine run after run, but another Mesa version may round a shading or
/// an edge differently: a few levels of color, and a few pixels along the silhouettes.
/// 0.5 % of 160 x 120 is 96 pixels: about one silhouette's worth of edge pixels turning.
constexpr int kChannelTolerance = 8;
constexpr double kMatchingFraction = 0.995;

/// The fraction of pixels whose channels all differ by at most `tolerance` (0 when the sizes
/// differ).
inline double matchingFraction(const rendering::Image& a, const rendering::Image& b,
                               int tolerance = kChannelTolerance) {
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size() ||
      a.rgba.empty())
    return 0.0;
  std::size_t matching = 0;
  const std::size_t pixels = a.rgba.size() / 4;
  for (std::size_t p = 0; p < pixels; ++p) {
    bool same = true;
    for (int c = 0; c < 4; ++c)
      same = same && std::abs(int(a.rgba[4 * p + c]) - int(b.rgba[4 * p + c])) <= tolerance;
    matching += same;
  }
  return static_cast<double>(matching) / static_cast<double>(pixels);
}

/// Reads `count` characters written by rendering::drawText at (x, y) (top-left, y downwards)
/// and `scale`, in a picture whose rows go from the top: each cell is lit where a pixel is
/// brighter than `threshold` (sum of r g b), and matched against every glyph of the font. An
/// unknown cell gives '?'.
inline std::string readText(const rendering::Image& image, int x, int y, int scale, int count,
                            int threshold = 600) {
  std::string out;
  const std::string alphabet = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZe .,-+:/=%()_";
  for (int i = 0; i < count; ++i) {
    const int left = x + i * rendering::kGlyphAdvance * scale;
    std::array<std::uint8_t, rendering::kGlyphHeight> rows{};
    for (int r = 0; r < rendering::kGlyphHeight; ++r)
      for (int c = 0; c < rendering::kGlyphWidth; ++c) {
        // The centre of the font pixel.
        const int px = left + c * scale + scale / 2, py = y + r * scale + scale / 2;
        if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
        const std::size_t at = (static_cast<std::size_t>(py) * image.width + px) * 4;
        const int sum = image.rgba[at] + image.rgba[at + 1] + image.rgba[at + 2];
        if (sum > threshold)
          rows[r] |= static_cast<std::uint8_t>(1u << (rendering::kGlyphWidth - 1 - c));
      }
    char found = '?';
    for (char candidate : alphabet)
      if (rendering::glyphRows(candidate) == rows) {
        found = candidate;
        break;
      }
    out += found;
  }
  return out;
}

}  // namespace stroma::test
