// SPDX-License-Identifier: MIT
// An OpenGL context that draws into memory (OSMesa, Mesa's software rasterizer): no display,
// no GPU, the same pixels on every run of one machine.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "stroma/rendering/PngImage.h"

namespace stroma::rendering {

class OffscreenContext {
 public:
  OffscreenContext() = default;
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  /// Creates an RGBA context with a depth buffer of width x height pixels and makes it
  /// current. Returns false with `error` when OSMesa cannot (no memory for the buffer, a size
  /// above its limit).
  bool create(int width, int height, std::string& error);
  /// The picture drawn so far, rows from the top.
  void readPixels(Image& image) const;
  /// The OpenGL implementation, for messages ("llvmpipe (LLVM 15, 256 bits)").
  std::string renderer() const;

  int width() const { return m_width; }
  int height() const { return m_height; }

 private:
  void* m_context = nullptr;  ///< OSMesaContext
  std::vector<std::uint8_t> m_buffer;
  int m_width = 0, m_height = 0;
};

}  // namespace stroma::rendering
