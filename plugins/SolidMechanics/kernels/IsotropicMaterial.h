// SPDX-License-Identifier: MIT
// Isotropic linear elasticity (Hooke's law): Lame parameters and the 6 x 6 elasticity matrix.
//
//   lambda = E nu / ((1 + nu)(1 - 2 nu)),   mu = E / (2 (1 + nu))          (Pa)
//   sigma = lambda tr(eps) I + 2 mu eps
//
// In Voigt form sigma = C eps with eps = (exx, eyy, ezz, gxy, gyz, gzx), engineering shear
// (gxy = 2 exy); Lame form as in Picinbono, Delingette, Ayache (seed 004, section 2.1) and
// Nesme's thesis, chapter 2 section 2.5 (seed 001):
//
//       | lambda+2mu  lambda      lambda      0   0   0  |
//       | lambda      lambda+2mu  lambda      0   0   0  |
//   C = | lambda      lambda      lambda+2mu  0   0   0  |
//       | 0           0           0           mu  0   0  |
//       | 0           0           0           0   mu  0  |
//       | 0           0           0           0   0   mu |
//
// Valid range: E > 0 and -1 < nu < 0.5 (C is then positive definite). The caller (the
// component that reads youngModulus and poissonRatio) checks it with isValidIsotropicMaterial
// and reports bad input; these functions do not check.
#pragma once

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::fem {

struct LameParameters {
  double lambda = 0;  ///< first Lame parameter (Pa)
  double mu = 0;      ///< shear modulus (Pa)
};

/// True when E > 0 and -1 < nu < 0.5, both finite.
bool isValidIsotropicMaterial(double youngModulus, double poissonRatio);

/// Lame parameters of Young's modulus E (Pa) and Poisson's ratio nu. Precondition: valid range.
LameParameters computeLameParameters(double youngModulus, double poissonRatio);

/// The 6 x 6 Voigt elasticity matrix C (Pa), sigma = C eps, engineering shear.
Matrix6d computeElasticityMatrix(const LameParameters& lame);

}  // namespace stroma::fem
