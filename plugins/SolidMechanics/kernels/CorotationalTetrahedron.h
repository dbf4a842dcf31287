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

#include <array>

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

/// Nodal vectors of a tetrahedron by coordinate: rows[a][i] is coordinate a of node i, so
/// that one row fills one 4-wide SIMD register (AVX). The layout of the products of a CG solve.
using TetrahedronRows = std::array<Eigen::Array4d, 3>;

inline TetrahedronRows toRows(const TetrahedronVectors& v) {
  TetrahedronRows r;
  for (int a = 0; a < 3; ++a) r[a] = v.row(a).transpose().array();
  return r;
}

inline TetrahedronVectors fromRows(const TetrahedronRows& r) {
  TetrahedronVectors v;
  for (int a = 0; a < 3; ++a) v.row(a) = r[a].matrix().transpose();
  return v;
}

/// Ke v for the stiffness in factored form Ke = B(G)^T C B(G), B the strain-displacement
/// matrix of the gradients G (StrainDisplacement.h), without forming Ke:
///
///   H = v G^T (displacement gradient), eps = (H00, H11, H22, H01 + H10, H12 + H21, H20 + H02),
///   s = C eps, (Ke v)_i = S G_i with S the symmetric 3 x 3 matrix of s.
///
/// With G = sqrt(|V|) grad N (columns: nodes) it is computeTetrahedronStiffness's Ke to
/// round-off. About 110 multiply-adds, on rows of 4 nodes; it reads the 12 numbers of G (C is
/// shared by the elements of one material) instead of Ke's 144.
EIGEN_ALWAYS_INLINE TetrahedronRows multiplyFactoredStiffness(const TetrahedronRows& G,
                                                              const Matrix6d& C,
                                                              const TetrahedronRows& v) {
  Eigen::Matrix3d H;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) H(a, b) = (v[a] * G[b]).sum();
  Vector6d strain;
  strain << H(0, 0), H(1, 1), H(2, 2), H(0, 1) + H(1, 0), H(1, 2) + H(2, 1), H(2, 0) + H(0, 2);
  const Vector6d s = C * strain;
  // f_a = sum_b S(a, b) G_b with S the symmetric stress matrix of s.
  TetrahedronRows f;
  f[0] = s[0] * G[0] + s[3] * G[1] + s[5] * G[2];
  f[1] = s[3] * G[0] + s[1] * G[1] + s[4] * G[2];
  f[2] = s[5] * G[0] + s[4] * G[1] + s[2] * G[2];
  return f;
}

/// M v for a 3 x 3 matrix M (a rotation or its transpose) applied to every node.
EIGEN_ALWAYS_INLINE TetrahedronRows rotateRows(const Eigen::Matrix3d& M, const TetrahedronRows& v) {
  TetrahedronRows r;
  for (int a = 0; a < 3; ++a) r[a] = M(a, 0) * v[0] + M(a, 1) * v[1] + M(a, 2) * v[2];
  return r;
}

/// Elastic force f = -R Ke (R^T x - X) (N) with Ke factored (multiplyFactoredStiffness), by
/// rows; u is taken relative to node 0 as in computeCorotatedDisplacement.
EIGEN_ALWAYS_INLINE TetrahedronRows computeFactoredForce(const TetrahedronRows& G,
                                                         const Matrix6d& C,
                                                         const Eigen::Matrix3d& R,
                                                         const TetrahedronRows& x,
                                                         const TetrahedronRows& X) {
  TetrahedronRows relative;
  for (int a = 0; a < 3; ++a) relative[a] = x[a] - x[a][0];
  TetrahedronRows u = rotateRows(R.transpose(), relative);
  for (int a = 0; a < 3; ++a) u[a] -= X[a] - X[a][0];
  return rotateRows(-R, multiplyFactoredStiffness(G, C, u));
}

/// Force differential df = -R Ke R^T dx (N) with Ke factored, by rows.
EIGEN_ALWAYS_INLINE TetrahedronRows computeFactoredDForce(const TetrahedronRows& G,
                                                          const Matrix6d& C,
                                                          const Eigen::Matrix3d& R,
                                                          const TetrahedronRows& dx) {
  return rotateRows(-R, multiplyFactoredStiffness(G, C, rotateRows(R.transpose(), dx)));
}

/// The factor G of computeTetrahedronStiffness's Ke = B(G)^T (C / scale) B(G) (see
/// multiplyFactoredStiffness): the rest shape-function gradients times sqrt(scale |V|), or zero
/// for an element without stiffness. Components with one Poisson ratio and a Young modulus per
/// element pass scale = E_e and share C(E = 1).
TetrahedronRows computeStiffnessFactor(const CorotationalTetrahedron& element, double scale);

}  // namespace stroma::fem
