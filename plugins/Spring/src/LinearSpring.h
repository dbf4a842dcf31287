// SPDX-License-Identifier: MIT
// One spring between two points, and how a scene writes a list of them: SOFA's format,
// "index1 index2 stiffness damping restLength" per spring, springs one after the other:
//   spring="0 1 100 5 1.0   1 2 100 5 1.0"
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/DataTraits.h"

namespace stroma {

struct LinearSpring {
  std::uint32_t m1 = 0, m2 = 0;  ///< point of the first state, point of the second state
  double ks = 0;                 ///< stiffness (N/m)
  double kd = 0;                 ///< damping along the spring (N s/m)
  double restLength = 0;         ///< (m)
  bool elongationOnly = false;   ///< no force when shorter than the rest length
  bool operator==(const LinearSpring&) const = default;
};

template <>
struct DataTraits<std::vector<LinearSpring>> {
  static std::string typeName() {
    return "list of springs 'index1 index2 stiffness damping restLength'";
  }
  static bool parse(std::string_view text, std::vector<LinearSpring>& springs, std::string& error) {
    TokenReader in(text);
    const std::size_t count = in.remaining();
    if (count % 5 != 0) {
      error =
          "expected 5 numbers per spring ('index1 index2 stiffness damping restLength'), "
          "got " +
          std::to_string(count) + " numbers: " + std::to_string(count / 5) + " springs and " +
          std::to_string(count % 5) + " numbers left over";
      return false;
    }
    std::vector<LinearSpring> result(count / 5);
    for (std::size_t k = 0; k < result.size(); ++k) {
      LinearSpring& s = result[k];
      std::string why;
      const bool ok = ElementTraits<std::uint32_t>::parseTokens(in, s.m1, why) &&
                      ElementTraits<std::uint32_t>::parseTokens(in, s.m2, why) &&
                      ElementTraits<double>::parseTokens(in, s.ks, why) &&
                      ElementTraits<double>::parseTokens(in, s.kd, why) &&
                      ElementTraits<double>::parseTokens(in, s.restLength, why);
      if (ok && !(std::isfinite(s.ks) && std::isfinite(s.kd) && std::isfinite(s.restLength)))
        why = "stiffness, damping and rest length must be finite";
      else if (ok && (s.ks < 0 || s.kd < 0 || s.restLength < 0))
        why = "stiffness, damping and rest length must be >= 0";
      if (!why.empty()) {
        error = "spring " + std::to_string(k) + ": " + why;
        return false;
      }
    }
    springs = std::move(result);
    return true;
  }
  static void print(std::string& out, const std::vector<LinearSpring>& springs) {
    for (std::size_t k = 0; k < springs.size(); ++k) {
      const LinearSpring& s = springs[k];
      if (k) out += "  ";
      out += std::to_string(s.m1) + ' ' + std::to_string(s.m2) + ' ';
      ElementTraits<double>::print(out, s.ks);
      out += ' ';
      ElementTraits<double>::print(out, s.kd);
      out += ' ';
      ElementTraits<double>::print(out, s.restLength);
    }
  }
};

}  // namespace stroma
