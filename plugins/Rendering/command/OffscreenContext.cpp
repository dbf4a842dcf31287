// SPDX-License-Identifier: MIT
#include "OffscreenContext.h"

#include <GL/osmesa.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>

namespace stroma::rendering {

OffscreenContext::~OffscreenContext() {
  if (m_context) OSMesaDestroyContext(static_cast<OSMesaContext>(m_context));
}

namespace {

/// MemAvailable of /proc/meminfo in bytes, 0 when unknown.
double availableMemory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kib = 0;
  std::string unit;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024.0;
  return 0;
}

}  // namespace

bool OffscreenContext::create(int width, int height, std::string& error) {
  const std::string size = std::to_string(width) + " x " + std::to_string(height);
  // Our color buffer, OSMesa's color and depth buffers, the frame read back and PNG rows:
  // about 16 bytes a pixel. Refusing beats being killed by the kernel halfway through.
  const double needed = 16.0 * width * height, available = availableMemory();
  if (available > 0 && needed > available) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "a picture of %s pixels needs about %.1f GiB of memory, %.1f GiB are available",
                  size.c_str(), needed / (1 << 30), available / (1 << 30));
    error = text;
    return false;
  }
  try {
    m_buffer.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  } catch (const std::bad_alloc&) {
    error = "not enough memory for a picture of " + size + " pixels";
    return false;
  }
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context) {
    error = "OSMesa could not create an OpenGL context";
    return false;
  }
  m_context = context;
  if (!OSMesaMakeCurrent(context, m_buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
    error = "OSMesa refused a buffer of " + size + " pixels";
    return false;
  }
  GLint maxWidth = 0, maxHeight = 0;
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxWidth);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxHeight);
  if ((maxWidth > 0 && width > maxWidth) || (maxHeight > 0 && height > maxHeight)) {
    error = "a picture of " + size + " pixels is above this OSMesa's limit of " +
            std::to_string(maxWidth) + " x " + std::to_string(maxHeight);
    return false;
  }
  m_width = width;
  m_height = height;
  return true;
}

void OffscreenContext::readPixels(Image& image) const {
  glFinish();
  image.width = m_width;
  image.height = m_height;
  image.rgba.resize(m_buffer.size());
  // OSMesa's rows go from the bottom (its Y_UP default).
  const std::size_t stride = static_cast<std::size_t>(m_width) * 4;
  for (int row = 0; row < m_height; ++row)
    std::memcpy(image.rgba.data() + row * stride,
                m_buffer.data() + static_cast<std::size_t>(m_height - 1 - row) * stride, stride);
}

std::string OffscreenContext::renderer() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return text ? text : "unknown";
}

}  // namespace stroma::rendering
