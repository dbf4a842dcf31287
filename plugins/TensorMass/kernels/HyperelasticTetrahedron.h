// SPDX-License-Identifier: MIT
// Hyperelastic linear (P1) tetrahedron, element by element: St Venant-Kirchhoff and
// compressible neo-Hookean materials, with their exact tangent.
//
// In a tetrahedron of rest volume V and shape vectors alpha_j (fem::TetrahedronShape), with the
// displacements U_j = x_j - X_j:
//
//   H = sum_j U_j alpha_j^T,  F = I + H      (displacement and deformation gradients)
//   f_j = -V P alpha_j,  P = dW/dF           (first Piola-Kirchhoff stress, energy density W)
//
// St Venant-Kirchhoff (Picinbono et al., seed 004, eqs. 10 and 11):
//   E = 1/2 (H + H^T + H^T H),  W = lambda/2 (tr E)^2 + mu tr E^2,  S = lambda tr E I + 2 mu E,
//   P = F S,  dP = dF S + F dS,  dS = lambda tr(dE) I + 2 mu dE,  dE = sym(F^T dF).
// E is computed from H, not from F^T F - I, so that small strains keep their digits.
//
// Neo-Hookean, compressible (Bonet and Wood, Nonlinear continuum mechanics for finite element
// analysis, 2nd ed., 2008, eq. 6.28):
//   J = det F,  W = mu/2 (tr(F^T F) - 3) - mu ln J + lambda/2 (ln J)^2,
//   P = mu (F - F^-T) + lambda ln J F^-T,
//   dP = mu dF + (mu - lambda ln J) F^-T dF^T F^-T + lambda tr(F^-1 dF) F^-T.
// Both reduce to linear elasticity (lambda, mu) for small strains. Neo-Hookean needs J > 0:
// computeStress reports an inverted element instead.
#pragma once

#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"

namespace stroma::tensormass {

enum class HyperelasticMaterial { stVenantKirchhoff, neoHookean };

/// What the tangent needs of the state where the stress was computed.
struct MaterialPoint {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();  ///< deformation gradient
  /// St Venant-Kirchhoff: the second Piola-Kirchhoff stress S (Pa); neo-Hookean: F^-T.
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  double logJ = 0;  ///< ln det F (neo-Hookean)
};

/// H = sum_j U_j alpha_j^T of the vertex displacements u (column j = U_j).
inline Eigen::Matrix3d computeDisplacementGradient(const fem::TetrahedronVectors& alpha,
                                                   const fem::TetrahedronVectors& u) {
  return u * alpha.transpose();
}

/// P (Pa) at displacement gradient H, and the material point for the tangent. Returns false
/// (P unspecified) when the material needs det F > 0 and it is not.
bool computeStress(HyperelasticMaterial material, const fem::LameParameters& lame,
                   const Eigen::Matrix3d& H, MaterialPoint& point, Eigen::Matrix3d& P);

/// The energy density W (J/m^3) at H; infinity for neo-Hookean when det F <= 0.
double computeEnergyDensity(HyperelasticMaterial material, const fem::LameParameters& lame,
                            const Eigen::Matrix3d& H);

/// dP for a change dF of the deformation gradient at `point`.
Eigen::Matrix3d computeStressDifferential(HyperelasticMaterial material,
                                          const fem::LameParameters& lame,
                                          const MaterialPoint& point, const Eigen::Matrix3d& dF);

/// The 3 x 3 block d(P alpha_j)/dx_k at `point`, so that the element's tangent stiffness
/// block is df_j/dx_k = -V times it (symmetric over the element: block (k, j) is its
/// transpose).
Eigen::Matrix3d computeTangentBlock(HyperelasticMaterial material, const fem::LameParameters& lame,
                                    const MaterialPoint& point, const Eigen::Vector3d& alphaJ,
                                    const Eigen::Vector3d& alphaK);

}  // namespace stroma::tensormass
