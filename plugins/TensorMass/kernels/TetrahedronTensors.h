// SPDX-License-Identifier: MIT
// The stiffness tensors of one tetrahedron for the tensor-mass models (Picinbono, Delingette,
// Ayache, seed 004, eqs. 8, 13 and 14; Cotin's linear model, seed 000, eq. 1.9).
//
// With the shape vectors alpha_j = grad Lambda_j (1/m, seed 004 eq. 6: the gradients of the
// barycentric coordinates, fem::TetrahedronShape::gradients), a_jk = alpha_j . alpha_k, the
// volume V (m^3, absolute) and the Lame parameters lambda, mu (Pa), the St Venant-Kirchhoff
// energy of the tetrahedron in the displacements U_j = x_j - X_j of its vertices is (eq. 13)
//
//   W = sum_jk U_j^T B^jk U_k + sum_jkl (U_j . C^jkl)(U_k . U_l)
//                             + sum_jklm D^jklm (U_j . U_k)(U_l . U_m)
//   B^jk   = V [lambda/2 alpha_j alpha_k^T + mu/2 (alpha_k alpha_j^T + a_jk I)]      (eq. 8)
//   C^jkl  = V [lambda/2 alpha_j a_kl + mu/2 (alpha_l a_jk + alpha_k a_jl)]          (eq. 14)
//   D^jklm = V [lambda/8 a_jk a_lm + mu/4 a_jm a_kl]                                  (eq. 14)
//
// (the paper folds V into the shape vectors). The linear model keeps the first sum.
//
// The tensor-mass models store W grouped by the vertices each term involves (seed 004,
// table 1): this class gives the coefficient of each distinct term ("monomial") of W, summed
// over the orders of its indices, so that the grouped energy reads
//
//   W = sum_p 1/2 U_p^T K^pp U_p + sum_{p<j} U_p^T K^pj U_j
//     + sum_{j, {k,l}} (U_j . c(j;k,l)) (U_k . U_l) + sum_{{j,k},{l,m}} q(jk;lm) (U_j.U_k)(U_l.U_m)
//
// with K^pj = 2 B^pj (seed 000 eq. 1.9's tensor), c = cubic(), q = quartic().
#pragma once

#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"

namespace stroma::tensormass {

class TetrahedronTensors {
 public:
  /// Precondition: a non-degenerate shape (fem::computeTetrahedronShape reported ok).
  TetrahedronTensors(const fem::TetrahedronShape& shape, const fem::LameParameters& lame);

  /// K^jk = 2 B^jk (N/m): the force on vertex j due to the displacement of k is -K^jk U_k
  /// (linear part, seed 000 eq. 1.10). K^kj = (K^jk)^T; K^jj is symmetric.
  Eigen::Matrix3d stiffness(int j, int k) const;

  /// Coefficient vector (N/m^2) of the term (U_j . v)(U_k . U_l): C^jkl + C^jlk, or C^jkk
  /// when k = l.
  Eigen::Vector3d cubic(int j, int k, int l) const;

  /// Coefficient (N/m^3) of the term (U_j . U_k)(U_l . U_m): the sum of D over every order of
  /// the indices that gives the same product.
  double quartic(int j, int k, int l, int m) const;

  /// The tensors of seed 004, eqs. 8 and 14.
  Eigen::Matrix3d B(int j, int k) const;
  Eigen::Vector3d C(int j, int k, int l) const;
  double D(int j, int k, int l, int m) const;

 private:
  fem::TetrahedronVectors m_alpha;
  Eigen::Matrix4d m_dot;  // a_jk
  double m_volume;
  double m_lambda;
  double m_mu;
};

}  // namespace stroma::tensormass
