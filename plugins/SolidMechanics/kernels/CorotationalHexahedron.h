// SPDX-License-Identifier: MIT
// Corotational trilinear hexahedron with the rotation methods of SOFA's
// HexahedronFEMForceField (small, large, polar). Forces, corotational stiffness and energy are
// the templates of CorotationalElement.h (f = -R Ke (R^T x - X), K = R Ke R^T ignoring dR/dx,
// E = 1/2 u^T Ke u); this header adds the per-element constants and the rotation. Node order:
// TrilinearHexahedron.h.
//
// Rotations (Nesme thesis, seed 001, ch. 4 sec. 2, figure 4.1; Nesme et al. 2005):
// - small: R = I.
// - large: the edges of each of the 3 reference directions are averaged,
//     a = (x1 - x0 + x2 - x3 + x5 - x4 + x6 - x7) / 4      (direction xi)
//     b = (x3 - x0 + x2 - x1 + x7 - x4 + x6 - x5) / 4      (direction eta)
//   and the Gram-Schmidt (QR) frame N of (a, b) (computeFrameFromEdges) gives R = N N0^T, N0
//   the same frame of the rest shape. Defined for flat and inverted elements.
// - polar: R of the polar decomposition of the deformation gradient at the element centre,
//   F = sum_i x_i grad N_i(0)^T; when det F <= 0 (inverted element) it falls back to the large
//   (QR) frame, which stays a rotation and keeps pushing the element back.
// - svd: not offered by SOFA for hexahedra; here, Irving's SVD rotation of the centre F
//   (computeSvdRotation), which flips the smallest singular axis of an inverted element.
// A hexahedron's displacement field is trilinear, so with any rotation the force is only
// approximately -dE/dx (relative difference O(|u|/L), see CorotationalElement.h).
#pragma once

#include "SolidMechanics/kernels/CorotationalElement.h"
#include "SolidMechanics/kernels/FemTypes.h"
#include "SolidMechanics/kernels/RotationExtraction.h"

namespace stroma::fem {

/// Per-element constants, computed once from the rest shape; the step only reads them.
struct CorotationalHexahedron {
  static constexpr int nodeCount = 8;
  using Vectors = HexahedronVectors;

  HexahedronVectors restPositions = HexahedronVectors::Zero();        ///< X (m)
  Eigen::Matrix3d restFrameTransposed = Eigen::Matrix3d::Identity();  ///< N0^T, for large
  HexahedronVectors centreGradients = HexahedronVectors::Zero();      ///< grad N_i(0) (1/m)
  Matrix24d stiffness = Matrix24d::Zero();                            ///< Ke (N/m)
  double restVolume = 0;                                              ///< signed V (m^3)
};

/// Fills `element` from the rest positions X and the elasticity matrix C (IsotropicMaterial.h).
/// Reports `degenerate` as computeHexahedronStiffness does.
ElementStatus computeCorotationalHexahedron(const HexahedronVectors& rest, const Matrix6d& C,
                                            CorotationalHexahedron& element);

/// Gram-Schmidt frame of the averaged xi and eta edges of the positions x (see above).
Eigen::Matrix3d computeHexahedronFrame(const HexahedronVectors& x);

/// Deformation gradient at the element centre, F = sum_i x_i grad N_i(0)^T (dimensionless).
Eigen::Matrix3d computeCentreDeformationGradient(const CorotationalHexahedron& element,
                                                 const HexahedronVectors& x);

/// Element rotation R (a proper rotation) of the current positions x by `method`.
Eigen::Matrix3d computeRotation(RotationMethod method, const CorotationalHexahedron& element,
                                const HexahedronVectors& x);

}  // namespace stroma::fem
