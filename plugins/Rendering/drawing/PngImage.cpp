// SPDX-License-Identifier: MIT
#include "stroma/rendering/PngImage.h"

#include <png.h>

#include <algorithm>
#include <cstring>

namespace stroma::rendering {

// libpng's simplified API (1.6) converts any PNG to 8-bit RGBA and reports errors as text
// instead of longjmp-ing through our frames.

bool readPng(const std::filesystem::path& file, Image& image, std::string& error) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, file.c_str())) {
    error = png.message[0] ? png.message : "not a PNG file";
    png_image_free(&png);
    return false;
  }
  png.format = PNG_FORMAT_RGBA;
  // Refuse sizes whose buffer would not fit comfortably (a corrupt header can claim anything).
  const std::size_t bytes = PNG_IMAGE_SIZE(png);
  if (png.width == 0 || png.height == 0 || png.width > 32768 || png.height > 32768) {
    error = "unreasonable size " + std::to_string(png.width) + " x " + std::to_string(png.height);
    png_image_free(&png);
    return false;
  }
  std::vector<std::uint8_t> pixels(bytes);
  if (!png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr)) {
    error = png.message[0] ? png.message : "corrupt PNG data";
    png_image_free(&png);
    return false;
  }
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgba = std::move(pixels);
  return true;
}

bool writePng(const std::filesystem::path& file, const Image& image, std::string& error) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    error = "no pixels to write";
    return false;
  }
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGBA;
  // Frames are written every few steps: speed over size (about 4 times faster, 20 % larger).
  png.flags = PNG_IMAGE_FLAG_FAST;
  if (!png_image_write_to_file(&png, file.c_str(), 0, image.rgba.data(), 0, nullptr)) {
    error = png.message[0] ? png.message : "cannot write the file";
    png_image_free(&png);
    return false;
  }
  return true;
}

void flipRows(Image& image) {
  const std::size_t stride = static_cast<std::size_t>(image.width) * 4;
  for (int top = 0, bottom = image.height - 1; top < bottom; ++top, --bottom)
    std::swap_ranges(image.rgba.begin() + top * stride, image.rgba.begin() + (top + 1) * stride,
                     image.rgba.begin() + bottom * stride);
}

}  // namespace stroma::rendering
