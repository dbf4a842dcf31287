// SPDX-License-Identifier: MIT
// Patch test: an affine displacement u(X) = A X + c imposed on the boundary of a patch of
// elements is the exact solution inside for any element that reproduces linear fields
// (constant strain); linear tetrahedra and trilinear hexahedra must match it to round-off.
// MacNeal & Harder, "A proposed standard set of problems to test finite element accuracy",
// Finite Elements in Analysis and Design 1, 1985: A = 1e-3 [[1, 1/2, 1/2], [1/2, 1, 1/2],
// [1/2, 1/2, 1]] (strains 1e-3, engineering shears 1e-3; ../shared/REFERENCES.md).
#pragma once

#include <Eigen/Core>

namespace stroma::reference {

struct AffinePatch {
  Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();     ///< A = du/dX
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  ///< c

  /// MacNeal and Harder's 3-D patch field (translation zero).
  static AffinePatch macNealHarder() {
    AffinePatch p;
    p.gradient << 1, 0.5, 0.5, 0.5, 1, 0.5, 0.5, 0.5, 1;
    p.gradient *= 1e-3;
    return p;
  }

  Eigen::Vector3d displacement(const Eigen::Vector3d& X) const {
    return gradient * X + translation;
  }
  /// Small strain (A + A^T) / 2, the same everywhere.
  Eigen::Matrix3d strain() const { return (gradient + gradient.transpose()) / 2; }
};

}  // namespace stroma::reference
