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

/// Corotated displacement u = R^T x - X (m) of an element at rest positions X, up to a uniform
/// translation that Ke ignores: it is computed relative to node 0,
/// u_i = R^T (x_i - x_0) - (X_i - X_0), so that elements far from the origin keep their
/// precision (energy error eps |Ke| |u|^2, not eps |Ke| |x|^2).
template <int N>
NodalVectors<N> computeCorotatedDisplacement(const NodalVectors<N>& rest, const Eigen::Matrix3d& R,
                                             const NodalVectors<N>& x) {
  const Eigen::Vector3d x0 = x.col(0), X0 = rest.col(0);
  return R.transpose() * (x.colwise() - x0) - (rest.colwise() - X0);
}

/// Ke v, the element matrix times a node-major vector: a sum of Ke's columns, written out so
/// that the compiler keeps the 3N sums in registers (for 24 x 24 Eigen calls its general
/// matrix-vector product: the product df = -R Ke R^T dx over 32^3 hexahedra sharing one Ke
/// took 2.55 ms of CPU against 2.25 ms this way, bench hexahedronAddDForce).
template <int N>
ElementVector<N> multiplyStiffness(const ElementMatrix<N>& Ke, const NodalVectors<N>& v) {
  const auto vector = asElementVector<N>(v);
  ElementVector<N> result = Ke.col(0) * vector[0];
  for (int k = 1; k < 3 * N; ++k) result.noalias() += Ke.col(k) * vector[k];
  return result;
}

/// Elastic force f = -R Ke (R^T x - X) (N), column i = force on node i.
template <int N>
NodalVectors<N> computeForce(const ElementMatrix<N>& Ke, const NodalVectors<N>& rest,
                             const Eigen::Matrix3d& R, const NodalVectors<N>& x) {
  const NodalVectors<N> u = computeCorotatedDisplacement<N>(rest, R, x);
  NodalVectors<N> stiffnessTimesU;
  Eigen::Map<ElementVector<N>>(stiffnessTimesU.data()) = multiplyStiffness<N>(Ke, u);
  return -R * stiffnessTimesU;
}

/// Force differential df = -R Ke R^T dx (N) of a position differential dx (m): the product
/// with the corotational stiffness, without assembling it.
template <int N>
NodalVectors<N> computeDForce(const ElementMatrix<N>& Ke, const Eigen::Matrix3d& R,
                              const NodalVectors<N>& dx) {
  const NodalVectors<N> localDx = R.transpose() * dx;
  NodalVectors<N> localDf;
  Eigen::Map<ElementVector<N>>(localDf.data()) = multiplyStiffness<N>(Ke, localDx);
  return -R * localDf;
}

/// Corotational stiffness K = R_N Ke R_N^T (3N x 3N, N/m), R_N = diag(R, ..., R), for a
/// symmetric Ke. Computed as two products by 3N x 3 column panels, which vectorize along the
/// 3N rows: A = Ke R_N^T, then K = A^T R_N^T, since A^T = R_N Ke^T = R_N Ke. Every Ke of the
/// kernels is symmetric up to round-off (sums of B^T C B), so K is R Ke R^T to round-off
/// (about 2 times faster than 3 x 3 block products, measured on hexahedra).
template <int N>
ElementMatrix<N> computeStiffness(const ElementMatrix<N>& Ke, const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d Rt = R.transpose();
  ElementMatrix<N> A;
  for (int j = 0; j < N; ++j)
    A.template middleCols<3>(3 * j).noalias() = Ke.template middleCols<3>(3 * j) * Rt;
  const ElementMatrix<N> At = A.transpose();
  ElementMatrix<N> K;
  for (int j = 0; j < N; ++j)
    K.template middleCols<3>(3 * j).noalias() = At.template middleCols<3>(3 * j) * Rt;
  return K;
}

/// Potential energy E = 1/2 u^T Ke u (J) with u = R^T x - X.
template <int N>
double computeEnergy(const ElementMatrix<N>& Ke, const NodalVectors<N>& rest,
                     const Eigen::Matrix3d& R, const NodalVectors<N>& x) {
  const NodalVectors<N> u = computeCorotatedDisplacement<N>(rest, R, x);
  const auto uVector = asElementVector<N>(u);
  return 0.5 * uVector.dot(Ke * uVector);
}

// The same on an element's constants (`restPositions`, `stiffness`).

template <class Element>
typename Element::Vectors computeCorotatedDisplacement(const Element& element,
                                                       const Eigen::Matrix3d& R,
                                                       const typename Element::Vectors& x) {
  static_assert(std::is_same_v<typename Element::Vectors, NodalVectors<Element::nodeCount>>,
                "Element must expose nodeCount and Vectors = NodalVectors<nodeCount>.");
  return computeCorotatedDisplacement<Element::nodeCount>(element.restPositions, R, x);
}

template <class Element>
typename Element::Vectors computeForce(const Element& element, const Eigen::Matrix3d& R,
                                       const typename Element::Vectors& x) {
  return computeForce<Element::nodeCount>(element.stiffness, element.restPositions, R, x);
}

template <class Element>
typename Element::Vectors computeDForce(const Element& element, const Eigen::Matrix3d& R,
                                        const typename Element::Vectors& dx) {
  return computeDForce<Element::nodeCount>(element.stiffness, R, dx);
}

template <class Element>
ElementMatrix<Element::nodeCount> computeStiffness(const Element& element,
                                                   const Eigen::Matrix3d& R) {
  return computeStiffness<Element::nodeCount>(element.stiffness, R);
}

template <class Element>
double computeEnergy(const Element& element, const Eigen::Matrix3d& R,
                     const typename Element::Vectors& x) {
  return computeEnergy<Element::nodeCount>(element.stiffness, element.restPositions, R, x);
}

}  // namespace stroma::fem
