// SPDX-License-Identifier: MIT
// The fiber reinforcement of one linear tetrahedron, corotational: its energy measured in the
// frame of the polar rotation of the element, so that the fibers turn with the element, with
// the exact gradient and Hessian (what an implicit solver and the generic force-field test
// need).
//
// With the shape-function gradients g_i (column i of TetrahedronShape::gradients), the
// deformation gradient F = sum_i x_i g_i^T, its polar decomposition F = R S (S symmetric), the
// corotated strain eps = S - I (= sym(R^T F) - I) and the Voigt matrix C_r of the
// reinforcement about the rest fiber direction (TransverselyIsotropicMaterial.h):
//
//   E = |V| / 2 eps : C_r : eps,    sigma = C_r : eps (symmetric, rest frame).
//
// dE = |V| sigma : dS with dS = R^T dF - Omega S, Omega = R^T dR = [omega]x. For a symmetric S,
// [w]x S + S [w]x = [G w]x with G = tr(S) I - S, so the skew part of R^T dF = Omega S + dS
// gives omega = 2 G^-1 axial(skew(R^T dF)). With m = axial(skew(S sigma)) and k = G^-1 m,
//
//   P = dE/dF = |V| R (sigma + 2 [k]x),      f_i = -P g_i.
//
// For an isotropic material sigma and S commute, k = 0 and P = |V| R sigma: the classical
// corotational force. An anisotropic sigma does not commute with S: the term 2 [k]x is the
// derivative of the rotation, needed for f = -dE/dx exactly. The Hessian follows from
// dP = |V| (R Omega (sigma + 2 [k]x) + R (dsigma + 2 [dk]x)), dsigma = C_r : dS,
// dk = G^-1 (dm - dG k), dm = axial(skew(dS sigma + S dsigma)), dG = tr(dS) I - dS, for the
// 12 unit directions dF = e_c g_j^T. At rest it is the linear element matrix V B^T C_r B.
//
// Rotation: fem::computePolarRotation (Higham's iteration; an inverted or nearly flat element
// falls back to the SVD rotation). G is invertible while no two eigenvalues of S sum to zero,
// true for every element that is not inverted; otherwise the rotation terms are dropped and
// the status says so.
#pragma once

#include "SolidMechanics/kernels/FemTypes.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"

namespace stroma::anisotropy {

/// What computeCorotationalReinforcement reports: `inverted` when G = tr(S) I - S is singular
/// (an inverted element); energy, force and tangent are then those of the rotation without its
/// derivative, finite but not exactly consistent.
enum class CorotationalStatus { ok, inverted };

/// Energy (J), nodal forces f = -dE/dx (N, column i on node i) and, when `hessian` is not
/// null, d2E/dx2 (N/m, 12 x 12, node-major, symmetric) of the corotational reinforcement of
/// the tetrahedron of rest shape `shape` at positions `x`, C_r about the rest fiber direction.
CorotationalStatus computeCorotationalReinforcement(const fem::TetrahedronShape& shape,
                                                    const fem::Matrix6d& Cr,
                                                    const fem::TetrahedronVectors& x,
                                                    double& energy, fem::TetrahedronVectors& force,
                                                    fem::Matrix12d* hessian);

}  // namespace stroma::anisotropy
