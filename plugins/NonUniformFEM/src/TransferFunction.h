// SPDX-License-Identifier: MIT
// Piecewise-linear transfer function from an image value to a material value (Young's
// modulus, density), written in a scene as "v0 y0 v1 y1 ..." with v0 < v1 < ...: linear
// between the given points, constant beyond the first and the last (an image value outside
// the table takes its nearest end).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stroma::nonuniform {

class TransferFunction {
 public:
  /// Reads "v0 y0 v1 y1 ..."; on bad input returns nothing and sets `why`: an odd count, no
  /// point, a value that is not finite, image values not strictly increasing, or an output
  /// below `minimum` (or equal to it when `strict`): "gives E = -5 at image value 3".
  static std::optional<TransferFunction> parse(std::span<const double> pairs, double minimum,
                                               bool strict, std::string& why);

  double operator()(double imageValue) const;

 private:
  std::vector<double> m_inputs, m_outputs;
};

}  // namespace stroma::nonuniform
