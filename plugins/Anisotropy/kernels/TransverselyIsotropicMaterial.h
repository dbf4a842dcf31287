// SPDX-License-Identifier: MIT
// Transversely isotropic linear elasticity about a unit fiber direction a: the strain energy of
// a fiber-reinforced material in Spencer's form (A. J. M. Spencer, "Continuum Theory of the
// Mechanics of Fibre-Reinforced Composites", CISM courses 282, Springer 1984), the material of
// the fiber-reinforced tissue that seed 004 (section 2.1) points to in its reference [9]
// (Picinbono, Lombardo, Delingette, Ayache 2001, linear anisotropic elasticity). With
// A = a (x) a and the small strain eps, the energy density is
//
//   W = lambda/2 (tr eps)^2 + mu_T tr(eps^2)                                  (isotropic part)
//     + alpha (tr eps)(a.eps a) + 2 (mu_L - mu_T) a.eps^2 a + beta/2 (a.eps a)^2   (reinforcement)
//
//   sigma = lambda tr(eps) I + 2 mu_T eps
//         + alpha ((a.eps a) I + tr(eps) A) + 2 (mu_L - mu_T)(A eps + eps A) + beta (a.eps a) A.
//
// With the fiber along axis 1, in Voigt form (engineering shear, FemTypes.h):
//   C11 = lambda + 2 alpha + beta + 4 mu_L - 2 mu_T,  C12 = C13 = lambda + alpha,
//   C22 = C33 = lambda + 2 mu_T,  C23 = lambda,  C44 = C66 = mu_L (planes containing a),
//   C55 = mu_T (the plane across a).
//
// Engineering constants (E_L along a, E_T across, nu_LT the contraction across a under a load
// along it, nu_TT in the plane across a, G_LT the shear modulus of planes containing a) give,
// with D = (1 + nu_TT)(1 - nu_TT - 2 nu_LT^2 E_T / E_L):
//
//   mu_T   = E_T / (2 (1 + nu_TT))                      mu_L = G_LT
//   lambda = C23 = E_T (nu_TT + nu_LT^2 E_T / E_L) / D
//   alpha  = C12 - lambda,   C12 = E_T nu_LT (1 + nu_TT) / D
//   beta   = C11 - 2 C12 + lambda + 2 mu_T - 4 mu_L,   C11 = E_L (1 - nu_TT^2) / D
//
// (C is the inverse of the compliance S11 = 1/E_L, S12 = -nu_LT/E_L, S22 = 1/E_T,
// S23 = -nu_TT/E_T, S44 = 1/G_LT, S55 = 2 (1 + nu_TT)/E_T). The material is positive definite
// exactly when E_L, E_T, G_LT > 0, -1 < nu_TT < 1 and nu_LT^2 < (1 - nu_TT) E_L / (2 E_T).
// Its isotropic part (lambda, mu_T) is what an isotropic force field with
//   E = mu_T (3 lambda + 2 mu_T) / (lambda + mu_T),  nu = lambda / (2 (lambda + mu_T))
// computes; it exists (E > 0, -1 < nu < 0.5) when 3 lambda + 2 mu_T > 0.
#pragma once

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::anisotropy {

using fem::Matrix6d;

/// The five engineering constants of a transversely isotropic material (Pa, Pa, -, -, Pa).
struct EngineeringConstants {
  double youngModulusL = 0;   ///< E_L, along the fiber (Pa)
  double youngModulusT = 0;   ///< E_T, across the fiber (Pa)
  double poissonRatioLT = 0;  ///< nu_LT = -eps_T / eps_L under a load along the fiber
  double poissonRatioTT = 0;  ///< nu_TT = -eps_T' / eps_T under a load across the fiber
  double shearModulusLT = 0;  ///< G_LT, shear in planes containing the fiber (Pa)
};

/// Spencer's parameters: the isotropic part (lambda, mu_T) and the reinforcement (alpha, beta,
/// mu_L), all in Pa.
struct SpencerParameters {
  double lambda = 0;
  double muT = 0;
  double alpha = 0;
  double beta = 0;
  double muL = 0;
};

/// What is wrong with a set of engineering constants, the first condition that fails.
enum class ConstantsStatus {
  ok,
  youngModulusL,   ///< E_L <= 0 or not finite
  youngModulusT,   ///< E_T <= 0 or not finite
  shearModulusLT,  ///< G_LT <= 0 or not finite
  poissonRatioTT,  ///< not -1 < nu_TT < 1
  poissonRatioLT,  ///< nu_LT^2 >= (1 - nu_TT) E_L / (2 E_T), or not finite: S not positive definite
};

/// Checks that the constants describe a positive-definite material.
ConstantsStatus checkEngineeringConstants(const EngineeringConstants& c);

/// Spencer's parameters of valid engineering constants (closed forms above).
SpencerParameters computeSpencerParameters(const EngineeringConstants& c);

/// The engineering constants of Spencer's parameters (inverse of the above), by inverting C.
/// Precondition: the material is positive definite.
EngineeringConstants computeEngineeringConstants(const SpencerParameters& p);

/// Young's modulus and Poisson's ratio of the isotropic material (lambda, mu).
struct IsotropicConstants {
  double youngModulus = 0;
  double poissonRatio = 0;
};
IsotropicConstants computeIsotropicConstants(double lambda, double mu);

/// The Voigt matrix (Pa, engineering shear) of the reinforcement alone, the last three terms of
/// W about the unit direction `a`: sigma_r = C_r eps and W_r = 1/2 eps^T C_r eps. Not definite
/// in general (negative when the fiber is softer than the matrix).
Matrix6d computeReinforcementElasticity(const Eigen::Vector3d& a, double alpha, double beta,
                                        double muL, double muT);

/// The Voigt matrix of the whole transversely isotropic material (isotropic part + the above).
Matrix6d computeTransverselyIsotropicElasticity(const Eigen::Vector3d& a,
                                                const SpencerParameters& p);

/// W_r of the symmetric strain `eps` written term by term (for tests of the matrix above).
double computeReinforcementEnergyDensity(const Eigen::Matrix3d& eps, const Eigen::Vector3d& a,
                                         double alpha, double beta, double muL, double muT);

}  // namespace stroma::anisotropy
