// SPDX-License-Identifier: MIT
// The linear strain-displacement matrix B of an element with N nodes, at one point.
//
// With gradients g_i = grad N_i (1/m) of the shape functions at that point, the Cauchy strain
// eps = sym(grad u) of the nodal displacements u (node-major 3N vector) is eps = B u, Voigt
// order (xx, yy, zz, xy, yz, zx) with engineering shear. The 6 x 3 block of node i is
//
//   | gx  0   0  |
//   | 0   gy  0  |
//   | 0   0   gz |
//   | gy  gx  0  |
//   | 0   gz  gy |
//   | gz  0   gx |
//
// (Nesme thesis, seed 001, appendix D section 1.1; Zienkiewicz and Taylor, vol. 1, ch. 6).
#pragma once

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::fem {

/// B (6 x 3N) from the shape-function gradients (column i = grad N_i, 1/m).
template <int N>
Eigen::Matrix<double, 6, 3 * N> computeStrainDisplacement(const NodalVectors<N>& gradients) {
  Eigen::Matrix<double, 6, 3 * N> B = Eigen::Matrix<double, 6, 3 * N>::Zero();
  for (int i = 0; i < N; ++i) {
    const double gx = gradients(0, i), gy = gradients(1, i), gz = gradients(2, i);
    const int c = 3 * i;
    B(0, c) = gx;
    B(1, c + 1) = gy;
    B(2, c + 2) = gz;
    B(3, c) = gy;
    B(3, c + 1) = gx;
    B(4, c + 1) = gz;
    B(4, c + 2) = gy;
    B(5, c) = gz;
    B(5, c + 2) = gx;
  }
  return B;
}

}  // namespace stroma::fem
