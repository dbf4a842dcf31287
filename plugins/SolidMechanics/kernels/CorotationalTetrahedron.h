// SPDX-License-Identifier: MIT
// Corotational linear tetrahedron with the rotation methods of SOFA's TetrahedronFEMForceField
// (small, large, polar, svd). Forces, corotational stiffness and energy are the templates of
// CorotationalElement.h (f = -R Ke (R^T x - X), K = R Ke R^T ignoring dR/dx,
// E = 1/2 u^T Ke u); this header adds the per-element constants and the rotation.
//
// Rotations, with F = Ds Dm^-1 the deformation gradient (Ds, Dm: current and rest edge
// matrices [x1 - x0, x2 - x0, x3 - x0]):
// - small: R = I (linear elasticity, Picinbono et al., seed 004, section 2.1).
// - large: R = N N0^T, N and N0 the Gram-Schmidt frames of edges (0-1, 0-2) in the current
//   and rest shapes (Nesme et al. 2005; seed 001, ch. 2 sec. 3.2.2, "Decomposition QR").
//   Cheap and defined for flat and inverted elements, but depends on the node numbering, and
//   the force is not exactly -dE/dx (see CorotationalElement.h).
// - polar: R of F = R S (Muller and Gross 2004), Newton iteration; det F <= 0 goes to svd.
// - svd: R from the SVD of F with the smallest singular axis flipped when det F < 0 (Irving
//   et al. 2004): the force then pushes an inverted element back to positive volume.
// For polar and svd the force is exactly -dE/dx.
//
// Measured cost per element (rotation + force; FemKernels_benchmark, README.md): small 45 ns,
// large 78 ns, polar 251 ns, svd 819 ns; stiffness R Ke R^T 100 ns; df product 25 ns.
#pragma once

#include "SolidMechanics/kernels/CorotationalElement.h"
#include "SolidMechanics/kernels/FemTypes.h"
#include "SolidMechanics/kernels/RotationExtraction.h"

namespace stroma::fem {

/// Per-element constants, computed once from the rest shape; the step only reads them.
struct CorotationalTetrahedron {
  static constexpr int nodeCount = 4;
  using Vectors = TetrahedronVectors;

  TetrahedronVectors restPositions = TetrahedronVectors::Zero();      ///< X (m)
  Eigen::Matrix3d restFrameTransposed = Eigen::Matrix3d::Identity();  ///< N0^T, for large
  Eigen::Matrix3d restEdgesInverse = Eigen::Matrix3d::Identity();     ///< Dm^-1 (1/m)
  Matrix12d stiffness = Matrix12d::Zero();                            ///< Ke (N/m)
  double restVolume = 0;                                              ///< signed V (m^3)
};

/// Fills `element` from the rest positions X and the elasticity matrix C (IsotropicMaterial.h).
/// Reports `degenerate` for a flat rest tetrahedron (computeTetrahedronShape).
ElementStatus computeCorotationalTetrahedron(const TetrahedronVectors& rest, const Matrix6d& C,
                                             CorotationalTetrahedron& element);

/// Deformation gradient F = Ds Dm^-1 (dimensionless) of the current positions x.
Eigen::Matrix3d computeDeformationGradient(const CorotationalTetrahedron& element,
                                           const TetrahedronVectors& x);

/// Element rotation R (a proper rotation) of the current positions x by `method`.
Eigen::Matrix3d computeRotation(RotationMethod method, const CorotationalTetrahedron& element,
                                const TetrahedronVectors& x);

}  // namespace stroma::fem
