// SPDX-License-Identifier: MIT
// The `method` keyword of the FEM force fields: how each element finds its rotation
// (RotationExtraction.h). SOFA's force fields spell the same methods in two ways:
// TetrahedronFEMForceField and HexahedronFEMForceField write small, large, polar, svd;
// FastTetrahedralCorotationalForceField writes qr for the Gram-Schmidt frame and polar2 for its
// second polar-decomposition algorithm. Both spellings are accepted; qr is large and polar2 is
// polar (the rotation of the polar decomposition is unique, only SOFA's algorithm differed).
#pragma once

#include <array>
#include <string_view>

#include "SolidMechanics/kernels/RotationExtraction.h"
#include "core/DataTraits.h"

namespace stroma {

enum class FemMethod { small, large, polar, svd, qr, polar2 };

template <>
struct EnumKeywords<FemMethod> {
  static constexpr std::array<std::string_view, 6> names{"small", "large", "polar",
                                                         "svd",   "qr",    "polar2"};
};

/// The kernels' rotation method of a keyword (qr is large, polar2 is polar).
constexpr fem::RotationMethod toRotationMethod(FemMethod method) {
  switch (method) {
    case FemMethod::small:
      return fem::RotationMethod::small;
    case FemMethod::large:
    case FemMethod::qr:
      return fem::RotationMethod::large;
    case FemMethod::polar:
    case FemMethod::polar2:
      return fem::RotationMethod::polar;
    case FemMethod::svd:
      return fem::RotationMethod::svd;
  }
  return fem::RotationMethod::large;
}

}  // namespace stroma
