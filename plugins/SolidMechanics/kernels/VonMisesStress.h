// SPDX-License-Identifier: MIT
// Von Mises stress of small-strain linear elasticity, from a displacement gradient.
//
// With H the displacement gradient (for a corotated element: H = R^T F - I, F the deformation
// gradient, R the element rotation), the small strain eps = (H + H^T) / 2 and an isotropic
// material of Lame parameters lambda, mu:
//
//   sigma = lambda tr(eps) I + 2 mu eps,   s = sigma - tr(sigma) / 3 I = 2 mu dev(eps),
//   von Mises = sqrt(3/2 s : s)   (Pa, the unit of the Young modulus).
//
// The volumetric part of sigma does not enter the von Mises stress, so only mu = E / (2 (1 + nu))
// is needed: the result is the same whatever the volumetric integration of the element. Under
// uniaxial tension sigma_xx (sigma's other entries 0) it is |sigma_xx| = E |eps_xx|.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace stroma::fem {

/// Von Mises stress (Pa) of the displacement gradient H (dimensionless), shear modulus mu (Pa).
inline double computeVonMisesStress(const Eigen::Matrix3d& H, double shearModulus) {
  const Eigen::Matrix3d strain = 0.5 * (H + H.transpose());
  const Eigen::Matrix3d deviator = strain - (strain.trace() / 3.0) * Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d s = 2.0 * shearModulus * deviator;
  return std::sqrt(1.5 * s.cwiseProduct(s).sum());
}

/// Shear modulus mu = E / (2 (1 + nu)) (Pa).
inline double computeShearModulus(double youngModulus, double poissonRatio) {
  return youngModulus / (2.0 * (1.0 + poissonRatio));
}

}  // namespace stroma::fem
