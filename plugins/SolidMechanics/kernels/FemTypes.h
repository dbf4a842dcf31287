// SPDX-License-Identifier: MIT
// Fixed-size types shared by the finite-element kernels, and the status they report.
//
// Conventions used by every kernel in this folder:
// - Nodal quantities of one element (positions, displacements, forces) are 3 x N matrices whose
//   column i belongs to node i. Their storage (column-major) is the node-major vector
//   (x0 y0 z0 x1 y1 z1 ...) that the 3N x 3N element matrices act on.
// - Voigt order of strain and stress: (xx, yy, zz, xy, yz, zx), engineering shear strain
//   (gamma_xy = 2 eps_xy), the order of SOFA's element matrices.
// - Forces are f = -dE/dx and stiffness K = d2E/dx2, so that df = -K dx.
// - SI units throughout: m, Pa, N, N/m, J, kg/m^3.
#pragma once

#include <Eigen/Core>

namespace stroma::fem {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

/// One 3-vector per node of an N-node element; column i is node i.
template <int N>
using NodalVectors = Eigen::Matrix<double, 3, N>;
/// Element matrix acting on the node-major vector of NodalVectors<N> (3N x 3N).
template <int N>
using ElementMatrix = Eigen::Matrix<double, 3 * N, 3 * N>;
/// The node-major vector view of NodalVectors<N> (3N x 1).
template <int N>
using ElementVector = Eigen::Matrix<double, 3 * N, 1>;

using TetrahedronVectors = NodalVectors<4>;
using HexahedronVectors = NodalVectors<8>;
using Matrix12d = ElementMatrix<4>;
using Matrix24d = ElementMatrix<8>;

/// What a kernel that reads a rest shape reports. `degenerate`: the element has (nearly) zero
/// volume, a Jacobian that changes sign inside it, or non-finite coordinates; the outputs are
/// then left unspecified and the caller must report the element and not use it.
enum class ElementStatus { ok, degenerate };

/// The node-major vector of nodal vectors, without copy.
template <int N>
Eigen::Map<const ElementVector<N>> asElementVector(const NodalVectors<N>& v) {
  return Eigen::Map<const ElementVector<N>>(v.data());
}

}  // namespace stroma::fem
