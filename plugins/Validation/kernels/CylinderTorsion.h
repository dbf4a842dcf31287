// SPDX-License-Identifier: MIT
// Saint-Venant torsion of a solid circular cylinder (linear elasticity): a torque T at the free
// end, the other end clamped. Circular sections stay plane (no warping) and turn rigidly by
//
//   phi(s) = T s / (G J),   J = pi R^4 / 2,   G = E / (2 (1 + nu))
//
// at distance s from the clamp (Timoshenko & Goodier, Theory of Elasticity, 1951, section
// 104); the surface shear stress is T R / J. Linear theory: the displacement is the
// infinitesimal rotation u = phi(s) e x (X - X_axis), valid while phi << 1.
#pragma once

#include <Eigen/Core>

namespace stroma::reference {

struct CylinderTorsion {
  double radius = 0.1;        ///< R
  double length = 1;          ///< L (the twist is clamped to s in [0, L])
  double torque = 1;          ///< T, right-handed about the axis
  double youngModulus = 1e6;  ///< E
  double poissonRatio = 0.3;  ///< nu

  /// True when R, L, E > 0, -1 < nu < 0.5, all finite.
  bool isValid() const;
  double polarMomentOfArea() const;  ///< J = pi R^4 / 2
  /// phi(s), the twist angle (rad) of the section at distance s from the clamp.
  double twistAngle(double s) const;
  /// Displacement of X for a cylinder along the unit vector `axis` clamped at `origin`.
  Eigen::Vector3d displacement(const Eigen::Vector3d& X, const Eigen::Vector3d& origin,
                               const Eigen::Vector3d& axis) const;
};

}  // namespace stroma::reference
