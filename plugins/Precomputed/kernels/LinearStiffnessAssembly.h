// SPDX-License-Identifier: MIT
// The assembled small-strain stiffness K (3n x 3n, N/m) of a linear tetrahedral mesh, the
// operator of the precomputed linear model: K = sum_e A_e^T Ke A_e with Ke the element stiffness
// of SolidMechanics/kernels/LinearTetrahedron.h (|V| B^T C B) and A_e the gather of the
// element's 4 nodes. Node-major dofs (x0 y0 z0 x1 ...), symmetric, positive semi-definite with
// the 6 rigid modes in its kernel.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace stroma::precomputed {

/// Node indices of one tetrahedron (the same layout as stroma::Tetrahedron).
using TetrahedronNodes = std::array<std::uint32_t, 4>;

/// Assembles K for rest points `points` (m), elements `tetrahedra`, Young's modulus E (Pa) and
/// Poisson's ratio nu. Returns false with `error` when the material is out of range
/// (E > 0, -1 < nu < 0.5), an element names a point out of range, or an element is degenerate
/// (the message names the element).
bool assembleLinearStiffness(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<TetrahedronNodes>& tetrahedra, double youngModulus,
                             double poissonRatio, Eigen::SparseMatrix<double>& K,
                             std::string& error);

}  // namespace stroma::precomputed
