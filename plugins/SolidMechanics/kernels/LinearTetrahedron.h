// SPDX-License-Identifier: MIT
// Linear (4-node, P1) tetrahedron with small-strain isotropic elasticity.
//
// Shape functions are barycentric coordinates, so their gradients are constant over the
// element. With the rest edge matrix Dm = [X1 - X0, X2 - X0, X3 - X0] (columns, m):
//
//   [grad N1, grad N2, grad N3] = Dm^-T,   grad N0 = -(grad N1 + grad N2 + grad N3)     (1/m)
//   V = det(Dm) / 6   (signed: positive when (X1-X0, X2-X0, X3-X0) is right-handed)  (m^3)
//   Ke = |V| B^T C B                                                               (N/m)
//   E = 1/2 u^T Ke u,   f = -Ke u   (u = x - X: nodal displacements)
//
// B is computeStrainDisplacement<4> (StrainDisplacement.h), C the Voigt elasticity matrix
// (IsotropicMaterial.h). With g_j = grad N_j, the 3 x 3 block (j, k) of Ke is
//   Ke_jk = |V| (lambda g_j g_k^T + mu g_k g_j^T + mu (g_j . g_k) I),
// the edge stiffness tensor 2 B^jk of the linear tensor-mass model of Picinbono, Delingette,
// Ayache (seed 004, section 2.1, eq. 8, where the volume is folded into the shape vectors), and
// the element of Nesme's thesis (seed 001, appendix D section 1.1). Both orientations of the
// rest tetrahedron are accepted; |V| makes Ke the same for both.
#pragma once

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::fem {

/// What the shape of a rest tetrahedron gives: constant shape-function gradients and volume.
struct TetrahedronShape {
  TetrahedronVectors gradients = TetrahedronVectors::Zero();  ///< column i = grad N_i (1/m)
  double volume = 0;                                          ///< signed volume (m^3)
};

/// Signed volume det(x1 - x0, x2 - x0, x3 - x0) / 6 (m^3) of any tetrahedron.
double computeTetrahedronVolume(const TetrahedronVectors& x);

/// Gradients and signed volume of the rest tetrahedron `rest`. Reports `degenerate` when
/// |det Dm| <= 1e-12 * (longest edge from node 0)^3 or a coordinate is not finite.
ElementStatus computeTetrahedronShape(const TetrahedronVectors& rest, TetrahedronShape& shape);

/// Element stiffness Ke = |V| B^T C B (12 x 12, N/m), symmetric positive semi-definite with
/// exactly 6 zero eigenvalues (the rigid modes) for a non-degenerate shape.
Matrix12d computeTetrahedronStiffness(const TetrahedronShape& shape, const Matrix6d& C);

/// Elastic force f = -Ke u (N, column i = force on node i) of nodal displacements u (m).
TetrahedronVectors computeLinearForce(const Matrix12d& Ke, const TetrahedronVectors& u);

}  // namespace stroma::fem
