// SPDX-License-Identifier: MIT
// Readable names for value-parameterized tests: without them GoogleTest names the cases
// /0, /1, ... and prints each parameter as a byte dump ("64-byte object <FB-A0 ...>"), which
// is what ctest then lists.
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <string_view>

namespace stroma::test {

/// A test name from a description, as GoogleTest accepts it (letters, digits, '_'): each word
/// capitalized and joined, a decimal point between digits written 'p', other characters
/// dropped. "Poisson ratio 0.5" -> "PoissonRatio0p5", "zero Young's modulus" ->
/// "ZeroYoungsModulus".
inline std::string testName(std::string_view description) {
  std::string name;
  bool newWord = true;
  for (std::size_t i = 0; i < description.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(description[i]);
    if (std::isalnum(c)) {
      name += newWord ? static_cast<char>(std::toupper(c)) : static_cast<char>(c);
      newWord = false;
    } else if (c == '.' && !name.empty() && std::isdigit(static_cast<unsigned char>(name.back())) &&
               i + 1 < description.size() &&
               std::isdigit(static_cast<unsigned char>(description[i + 1]))) {
      name += 'p';
    } else if (c != '\'') {  // "Young's" stays one word
      newWord = true;
    }
  }
  return name.empty() ? std::string("Unnamed") : name;
}

/// Name generator for INSTANTIATE_TEST_SUITE_P over parameters with a `what` description.
struct NameFromWhat {
  template <class Param>
  std::string operator()(const testing::TestParamInfo<Param>& info) const {
    return testName(info.param.what);
  }
};

}  // namespace stroma::test
