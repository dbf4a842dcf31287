// SPDX-License-Identifier: MIT
// Homogeneous uniaxial stress of a block: stretch lambda along one axis, the lateral faces free
// (zero lateral stress), for three isotropic materials with Lame parameters (lambda_L, mu) of
// E and nu:
//
//   linear (and corotational):  t = 1 - nu (lambda - 1),        P = E (lambda - 1)
//   St Venant-Kirchhoff, W = lambda_L/2 (tr E)^2 + mu tr E^2 (Picinbono et al., seed 004,
//     eq. 10): S_22 = 0 gives t^2 - 1 = -nu (lambda^2 - 1), and P = E lambda (lambda^2 - 1) / 2
//   compressible neo-Hookean, W = mu/2 (I1 - 3) - mu ln J + lambda_L/2 (ln J)^2 (Bonet & Wood
//     2008, eq. 6.28; the law of StandardTetrahedralFEMForceField materialName="NeoHookean"):
//     P = mu (F - F^-T) + lambda_L ln J F^-T; P_22 = 0 gives mu (t^2 - 1) + lambda_L ln(lambda
//     t^2) = 0, solved for t by Newton's method (the left side increases with t: one root), and
//     P = [mu (lambda^2 - 1) + lambda_L ln J] / lambda, J = lambda t^2.
//
// t is the lateral stretch, P the first Piola (nominal) stress along the axis: the force per
// unit of undeformed area. Values in ../shared/REFERENCES.md ("Homogeneous uniaxial stress").
// StVK has no lateral solution once nu (lambda^2 - 1) >= 1 and its P is not monotone below
// lambda = 1/sqrt(3) (P_min = -E / (3 sqrt 3)); lateralStretch then returns NaN.
#pragma once

#include <Eigen/Core>

namespace stroma::reference {

enum class UniaxialMaterial { linear, stVenantKirchhoff, neoHookean };

struct UniaxialStretch {
  UniaxialMaterial material = UniaxialMaterial::linear;
  double youngModulus = 1;    ///< E
  double poissonRatio = 0.3;  ///< nu, -1 < nu < 0.5

  /// True when E > 0 and -1 < nu < 0.5, both finite.
  bool isValid() const;

  /// t, the lateral stretch at axial stretch lambda > 0; NaN where none exists (StVK).
  double lateralStretch(double stretch) const;
  /// P, the nominal (first Piola) axial stress at axial stretch lambda; NaN where t is.
  double nominalStress(double stretch) const;
  /// The axial stretch whose nominal stress is P (bisection on the monotone branch: lambda >
  /// 1/sqrt(3) for StVK); NaN when P is out of reach (StVK below P_min).
  double stretchForNominalStress(double nominalStress) const;

  /// Displacement of the material point X of a block stretched along the unit vector `axis`
  /// about the fixed point `origin`: (lambda - 1) along the axis, (t - 1) across it.
  Eigen::Vector3d displacement(const Eigen::Vector3d& X, const Eigen::Vector3d& origin,
                               const Eigen::Vector3d& axis, double stretch) const;
};

}  // namespace stroma::reference
