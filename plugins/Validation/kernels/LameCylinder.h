// SPDX-License-Identifier: MIT
// Lame's thick-walled cylinder under internal pressure, plane strain: the closed-form
// reference of the volumetric-locking check (issue 7, item 6).
//
// A cylinder of inner radius a and outer radius b, pressure p on the inner face, outer face
// free, axial strain zero (plane strain). Linear isotropic material E, nu. Radial displacement
// (Timoshenko & Goodier, Theory of Elasticity, 1951, section 28, with plane-strain constants):
//
//   u_r(r) = (1 + nu) / E * p a^2 / (b^2 - a^2) * [ (1 - 2 nu) r + b^2 / r ]
//   sigma_rr(r)  = p a^2 / (b^2 - a^2) * (1 - b^2 / r^2)      (= -p at r = a, 0 at r = b)
//   sigma_tt(r)  = p a^2 / (b^2 - a^2) * (1 + b^2 / r^2)
//   sigma_zz     = nu (sigma_rr + sigma_tt)                   (plane strain)
//
// u_r satisfies the equilibrium equation u'' + u'/r - u/r^2 = 0 (tested by finite
// differences). Values of ../shared/REFERENCES.md: a = 1, b = 2, p = 1e-3, E = 1:
// u_r(a) = 1.906667e-3 (nu 0.3), 1.999666e-3 (nu 0.499). Valid for nu < 0.5 and nu = 0.5 alike.
// Units: whatever the caller uses consistently (lengths, pressure and E in the same units).
#pragma once

#include <Eigen/Core>

namespace stroma::reference {

struct LameCylinder {
  double innerRadius = 1;     ///< a (length)
  double outerRadius = 2;     ///< b > a (length)
  double pressure = 1e-3;     ///< p, internal pressure, positive pushes outwards (Pa)
  double youngModulus = 1;    ///< E (Pa)
  double poissonRatio = 0.3;  ///< nu, -1 < nu <= 0.5

  /// True when 0 < a < b, E > 0, -1 < nu <= 0.5, all finite.
  bool isValid() const;

  /// u_r(r), radial displacement at radius r > 0.
  double radialDisplacement(double r) const;
  /// sigma_rr(r), radial stress (negative: compression).
  double radialStress(double r) const;
  /// sigma_tt(r), hoop stress.
  double hoopStress(double r) const;
  /// Displacement of the point x: u_r(r) along the radial direction of (x, y), no axial
  /// component (the axis is z). Zero on the axis (outside the wall anyway).
  Eigen::Vector3d displacement(const Eigen::Vector3d& x) const;
};

}  // namespace stroma::reference
