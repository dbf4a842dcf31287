// SPDX-License-Identifier: MIT
// Reading binary numbers from the bytes of a mesh file, with bounds checked by the caller
// (has()) before each read, and errors that give the byte offset.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

namespace stroma::meshio {

class ByteCursor {
 public:
  ByteCursor(std::string_view data, std::size_t offset, bool bigEndian)
      : m_data(data),
        m_pos(offset),
        m_swap(bigEndian != (std::endian::native == std::endian::big)) {}

  /// True when `count` values of `size` bytes each remain (without overflow).
  bool has(std::size_t count, std::size_t size) const {
    if (m_pos > m_data.size()) return false;
    const std::size_t left = m_data.size() - m_pos;
    return size == 0 || count <= left / size;
  }

  /// Reads one value; has() must have been checked.
  template <class T>
  T read() {
    static_assert(std::is_arithmetic_v<T>, "ByteCursor reads numbers only.");
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, m_data.data() + m_pos, sizeof(T));
    if (m_swap)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    m_pos += sizeof(T);
    return value;
  }

  void skip(std::size_t bytes) { m_pos += bytes; }
  std::size_t offset() const { return m_pos; }

  /// "byte offset N: <text>".
  std::string at(std::string_view text) const {
    return "byte offset " + std::to_string(m_pos) + ": " + std::string(text);
  }
  /// The error for data cut short: "byte offset N: expected <what>, got the end of the file".
  std::string truncated(std::string_view what) const {
    return at("expected " + std::string(what) + ", got the end of the file (truncated file?)");
  }

 private:
  std::string_view m_data;
  std::size_t m_pos;
  bool m_swap;
};

}  // namespace stroma::meshio
