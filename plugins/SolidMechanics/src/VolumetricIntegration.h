// SPDX-License-Identifier: MIT
// The `volumetricIntegration` keyword of the FEM force fields: where the volumetric energy
// 1/2 kappa (tr eps)^2 is integrated, the locking-free options for nu close to 1/2
// (SolidMechanics/kernels/VolumetricSplit.h). One attribute name for both elements; the
// keywords each element offers differ, so each has its own enum (a keyword the element does
// not offer is refused by the parser with the list of those it does).
#pragma once

#include <array>
#include <string_view>

#include "SolidMechanics/kernels/VolumetricSplit.h"
#include "core/DataTraits.h"

namespace stroma {

/// Hexahedra: full (2 x 2 x 2 Gauss, locks as nu -> 1/2) or reduced (one volumetric strain per
/// element, the mean dilatation: selective reduced integration in its B-bar form).
enum class HexahedronVolumetricIntegration { full, reduced };

/// Tetrahedra: full (the linear tetrahedron's one point, locks as nu -> 1/2) or nodal (one
/// volumetric strain per vertex, Bonet and Burton's averaged nodal pressure).
enum class TetrahedronVolumetricIntegration { full, nodal };

template <>
struct EnumKeywords<HexahedronVolumetricIntegration> {
  static constexpr std::array<std::string_view, 2> names{"full", "reduced"};
};

template <>
struct EnumKeywords<TetrahedronVolumetricIntegration> {
  static constexpr std::array<std::string_view, 2> names{"full", "nodal"};
};

constexpr fem::VolumetricStiffness toVolumetricStiffness(HexahedronVolumetricIntegration v) {
  return v == HexahedronVolumetricIntegration::reduced ? fem::VolumetricStiffness::meanDilatation
                                                       : fem::VolumetricStiffness::full;
}

constexpr fem::VolumetricStiffness toVolumetricStiffness(TetrahedronVolumetricIntegration v) {
  return v == TetrahedronVolumetricIntegration::nodal ? fem::VolumetricStiffness::deviatoric
                                                      : fem::VolumetricStiffness::full;
}

}  // namespace stroma
