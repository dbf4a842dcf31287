// SPDX-License-Identifier: MIT
// Corotational linear elasticity of one element, once its rotation R is known (Felippa and
// Haugen 2005; Muller and Gross 2004; Nesme thesis, seed 001, ch. 2 sec. 3.2.2 and ch. 4
// sec. 2). Shared by CorotationalTetrahedron and CorotationalHexahedron.
//
// With rest positions X (3 x N), current positions x, the element stiffness Ke of the rest
// shape and the element rotation R = R(x):
//
//   u = R^T x - X                 corotated displacement (m), translations removed
//   E = 1/2 u^T Ke u              potential energy (J)
//   f = -R Ke u                   elastic force on the nodes (N)
//   K = R Ke R^T                  stiffness for implicit solves (N/m), df = -K dx
//
// Translations do not count: Ke annihilates the uniform R^T t. Rigid motions x = Q X + t give
// u = 0 for the large, polar and svd rotations, hence f = 0 and E = 0.
//
// Approximations, stated once:
// - K ignores dR/dx (the usual corotational tangent; Muller and Gross 2004). It is exact at
//   u = 0 (any rigidly moved rest shape) and differs from the true Jacobian by O(|u|)
//   otherwise. It is symmetric positive semi-definite, which implicit solvers rely on.
// - f is exactly -dE/dx when R^T F is symmetric for an isotropic material and a linear
//   displacement field: tetrahedra with the polar and svd rotations (the elastic torque
//   sum u_i x (Ke u)_i then vanishes), and trivially with small. With the large (QR) frame, and
//   for hexahedra with any rotation, f and -dE/dx differ by a term of relative size O(|u|/L):
//   the force is consistent with linear elasticity to first order but not exactly
//   conservative. Energy reports made with E are then approximate.
//
// Every function works on fixed-size stack values and allocates nothing.
#pragma once

#include <type_traits>

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::fem {

/// Corotated displacement u = R^T x - X (m), up to a uniform translation that Ke ignores: it
/// is computed relative to node 0, u_i = R^T (x_i - x_0) - (X_i - X_0), so that elements far
/// from the origin keep their precision (energy error eps |Ke| |u|^2, not eps |Ke| |x|^2).
template <class Element>
typename Element::Vectors computeCorotatedDisplacement(const Element& element,
                                                       const Eigen::Matrix3d& R,
                                                       const typename Element::Vectors& x) {
  static_assert(std::is_same_v<typename Element::Vectors, NodalVectors<Element::nodeCount>>,
                "Element must expose nodeCount and Vectors = NodalVectors<nodeCount>.");
  const Eigen::Vector3d x0 = x.col(0), X0 = element.restPositions.col(0);
  return R.transpose() * (x.colwise() - x0) - (element.restPositions.colwise() - X0);
}

/// Elastic force f = -R Ke (R^T x - X) (N), column i = force on node i.
template <class Element>
typename Element::Vectors computeForce(const Element& element, const Eigen::Matrix3d& R,
                                       const typename Element::Vectors& x) {
  constexpr int N = Element::nodeCount;
  const NodalVectors<N> u = computeCorotatedDisplacement(element, R, x);
  NodalVectors<N> stiffnessTimesU;
  Eigen::Map<ElementVector<N>>(stiffnessTimesU.data()).noalias() =
      element.stiffness * asElementVector<N>(u);
  return -R * stiffnessTimesU;
}

/// Force differential df = -R Ke R^T dx (N) of a position differential dx (m): the product
/// with the corotational stiffness, without assembling it.
template <class Element>
typename Element::Vectors computeDForce(const Element& element, const Eigen::Matrix3d& R,
                                        const typename Element::Vectors& dx) {
  constexpr int N = Element::nodeCount;
  const NodalVectors<N> localDx = R.transpose() * dx;
  NodalVectors<N> localDf;
  Eigen::Map<ElementVector<N>>(localDf.data()).noalias() =
      element.stiffness * asElementVector<N>(localDx);
  return -R * localDf;
}

/// Corotational stiffness K = R Ke R^T (3N x 3N, N/m), computed 3 x 3 block by block.
template <class Element>
ElementMatrix<Element::nodeCount> computeStiffness(const Element& element,
                                                   const Eigen::Matrix3d& R) {
  constexpr int N = Element::nodeCount;
  ElementMatrix<N> K;
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      const Eigen::Matrix3d blockTimesRt =
          element.stiffness.template block<3, 3>(3 * i, 3 * j) * R.transpose();
      K.template block<3, 3>(3 * i, 3 * j).noalias() = R * blockTimesRt;
    }
  }
  return K;
}

/// Potential energy E = 1/2 u^T Ke u (J) with u = R^T x - X.
template <class Element>
double computeEnergy(const Element& element, const Eigen::Matrix3d& R,
                     const typename Element::Vectors& x) {
  constexpr int N = Element::nodeCount;
  const NodalVectors<N> u = computeCorotatedDisplacement(element, R, x);
  const auto uVector = asElementVector<N>(u);
  return 0.5 * uVector.dot(element.stiffness * uVector);
}

}  // namespace stroma::fem
