// SPDX-License-Identifier: MIT
#include "simulation/Color.h"

#include <array>
#include <cctype>
#include <charconv>
#include <sstream>
#include <utility>
#include <vector>

namespace stroma {

namespace {

struct NamedColor {
  std::string_view name;
  double r, g, b;
};

// The names SOFA scenes use, with their usual RGB values.
constexpr std::array kNamedColors{
    NamedColor{"white", 1, 1, 1},      NamedColor{"black", 0, 0, 0},
    NamedColor{"red", 1, 0, 0},        NamedColor{"green", 0, 1, 0},
    NamedColor{"blue", 0, 0, 1},       NamedColor{"cyan", 0, 1, 1},
    NamedColor{"magenta", 1, 0, 1},    NamedColor{"yellow", 1, 1, 0},
    NamedColor{"gray", 0.5, 0.5, 0.5}, NamedColor{"grey", 0.5, 0.5, 0.5},
    NamedColor{"darkgray", 0.25, 0.25, 0.25}, NamedColor{"lightgray", 0.75, 0.75, 0.75},
    NamedColor{"orange", 1, 0.5, 0},   NamedColor{"purple", 0.5, 0, 0.5},
    NamedColor{"pink", 1, 0.75, 0.8},  NamedColor{"brown", 0.6, 0.3, 0.1},
    NamedColor{"olive", 0.5, 0.5, 0},  NamedColor{"navy", 0, 0, 0.5},
    NamedColor{"silver", 0.75, 0.75, 0.75},
};

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

bool parseColor(std::string_view text, Vec4d& rgba, std::string& error) {
  std::string trimmed(text);
  while (!trimmed.empty() && std::isspace(static_cast<unsigned char>(trimmed.back())))
    trimmed.pop_back();
  while (!trimmed.empty() && std::isspace(static_cast<unsigned char>(trimmed.front())))
    trimmed.erase(trimmed.begin());
  if (trimmed.empty()) {
    error = "empty color";
    return false;
  }
  if (trimmed.front() == '#') {
    if (trimmed.size() != 7 && trimmed.size() != 9) {
      error = "'" + trimmed + "' is not #rrggbb nor #rrggbbaa";
      return false;
    }
    std::array<double, 4> c{0, 0, 0, 1};
    for (std::size_t k = 0; k + 1 < trimmed.size(); k += 2) {
      const int hi = hexDigit(trimmed[k + 1]), lo = hexDigit(trimmed[k + 2]);
      if (hi < 0 || lo < 0) {
        error = "'" + trimmed + "' has a character that is not a hexadecimal digit";
        return false;
      }
      c[k / 2] = (hi * 16 + lo) / 255.0;
    }
    rgba = Vec4d(c[0], c[1], c[2], c[3]);
    return true;
  }
  if (std::isalpha(static_cast<unsigned char>(trimmed.front()))) {
    for (const NamedColor& n : kNamedColors)
      if (n.name == trimmed) {
        rgba = Vec4d(n.r, n.g, n.b, 1.0);
        return true;
      }
    std::string names;
    for (const NamedColor& n : kNamedColors) names += (names.empty() ? "" : ", ") + std::string(n.name);
    error = "unknown color name '" + trimmed + "' (known: " + names + ", #rrggbb, or 'r g b a')";
    return false;
  }
  std::istringstream in(trimmed);
  std::vector<double> values;
  std::string word;
  while (in >> word) {
    double v = 0;
    const char* end = word.data() + word.size();
    const char* begin = word.data();
    if (*begin == '+') ++begin;
    auto [ptr, ec] = std::from_chars(begin, end, v);
    if (ec != std::errc() || ptr != end) {
      error = "'" + word + "' in color '" + trimmed + "' is not a number";
      return false;
    }
    values.push_back(v);
  }
  if (values.size() != 3 && values.size() != 4) {
    error = "color '" + trimmed + "' has " + std::to_string(values.size()) +
            " numbers; expected 3 (r g b) or 4 (r g b a)";
    return false;
  }
  for (double v : values)
    if (!(v >= 0.0 && v <= 1.0)) {
      error = "color '" + trimmed + "' has a component outside [0, 1]";
      return false;
    }
  rgba = Vec4d(values[0], values[1], values[2], values.size() == 4 ? values[3] : 1.0);
  return true;
}

}  // namespace stroma
