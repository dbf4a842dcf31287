// SPDX-License-Identifier: MIT
// PNG files (libpng): textures in, pictures out.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace stroma::rendering {

/// 8-bit RGBA pixels, rows from the top.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height * 4
};

/// Reads any PNG (grey, palette, 16 bits, with or without alpha) as 8-bit RGBA. Returns false
/// with `error` (what is wrong with the file) when it cannot.
bool readPng(const std::filesystem::path& file, Image& image, std::string& error);
/// Writes RGBA pixels (rows from the top). Returns false with `error` when it cannot.
bool writePng(const std::filesystem::path& file, const Image& image, std::string& error);

/// OpenGL's glReadPixels rows go from the bottom: turns them over in place.
void flipRows(Image& image);

}  // namespace stroma::rendering
