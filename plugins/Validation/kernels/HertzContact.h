// SPDX-License-Identifier: MIT
// Hertz's contact of an elastic sphere (radius R, Young's modulus E, Poisson's ratio nu) with a
// rigid plane, frictionless, small strain (Johnson 1985, "Contact Mechanics", sections 3.9 and
// 4.2): with E* = E / (1 - nu^2) and d the approach of distant points of the sphere to the plane,
//
//   contact radius  a = sqrt(R d),   force  F = 4/3 E* sqrt(R) d^(3/2)        (eq. 4.22-4.23)
//   pressure        p(r) = p0 sqrt(1 - r^2 / a^2),   p0 = 3 F / (2 pi a^2).
//
// "Distant" means infinitely far: the sphere is taken as a half-space. A finite sphere is held
// or driven at a finite depth z below the contact (its centre: z = R), where the half-space
// field has not vanished. On the axis, integrating the strain of Hertz's stresses (Johnson eq.
// 3.45: sigma_z = -p0 / (1 + zeta^2), sigma_r = sigma_theta = p0 [-(1 + nu)(1 - zeta atan(1 /
// zeta)) + 1 / (2 (1 + zeta^2))], zeta = z / a) from z to infinity gives the displacement of
// the axis point at depth z towards the plane, relative to the distant points,
//
//   u(z) = d  2 / (pi (1 - nu))  [atan(1/zeta) - nu ((1 + zeta^2) atan(1/zeta) - zeta)],
//
// u(0) = d (the pole reaches the plane) and u(z) ~ d (2 / pi) (1 - 2 nu / 3) / ((1 - nu) zeta)
// far away. The approach of the point at depth z is then delta = d - u(z): at the centre of a
// sphere (nu = 0.3) delta is 5 % short of d at d / R = 0.5 %, 10 % at 2 %, so that F(delta) of
// the law above is 8 to 18 % under the half-space's own force at that approach.
#pragma once

namespace stroma::reference {

struct HertzContact {
  double youngModulus = 1;    ///< E of the sphere (Pa); the plane is rigid
  double poissonRatio = 0.3;  ///< nu, -1 < nu < 0.5
  double radius = 1;          ///< R

  /// True when E > 0, -1 < nu < 0.5 and R > 0, all finite.
  bool isValid() const;
  /// E* = E / (1 - nu^2).
  double effectiveModulus() const;
  /// F = 4/3 E* sqrt(R) d^(3/2) at the approach d of distant points (0 for d <= 0).
  double force(double indentation) const;
  /// u(z): how much less than d the axis point at depth z >= 0 approaches the plane.
  double axisLag(double indentation, double depth) const;
  /// The approach d of distant points at which the axis point at depth z approaches by
  /// `approach` (delta = d - u(z), solved for d by fixed-point iteration; it converges while
  /// u(z) < d / 2, that is z > about 1.2 a); NaN where it does not.
  double indentationForApproachAt(double approach, double depth) const;
};

}  // namespace stroma::reference
