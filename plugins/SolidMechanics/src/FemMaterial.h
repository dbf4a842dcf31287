// SPDX-License-Identifier: MIT
// The isotropic material of the FEM force fields, as the scene gives it: youngModulus (one
// value, or one per element) and poissonRatio. Checked once here for init() and for changes
// made while running.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>

namespace stroma {

/// What is wrong with a material, for a message: the field and the text.
struct MaterialProblem {
  std::string field;
  std::string text;
};

/// Checks that `youngModulus` has one value or one per element (elementCount `elements`), each
/// finite and > 0, and that -1 < poissonRatio < 0.5 (IsotropicMaterial.h): nothing when valid.
std::optional<MaterialProblem> checkMaterial(std::span<const double> youngModulus,
                                             double poissonRatio, std::size_t elementCount,
                                             const char* elements);

}  // namespace stroma
