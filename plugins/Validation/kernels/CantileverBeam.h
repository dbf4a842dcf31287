// SPDX-License-Identifier: MIT
// Small-deflection cantilever of rectangular section: the deflection w(s) at distance s from
// the clamp, Euler-Bernoulli or Timoshenko, for a tip load P and a uniform line load q (both
// may act together; linear theory superposes them).
//
//   Euler-Bernoulli (Timoshenko & Gere, Mechanics of Materials, 1972, tables of deflections):
//     tip load P:     w(s) = P s^2 (3 L - s) / (6 E I),            w(L) = P L^3 / (3 E I)
//     line load q:    w(s) = q s^2 (6 L^2 - 4 L s + s^2) / (24 E I), w(L) = q L^4 / (8 E I)
//   Timoshenko adds the shear deflection (the shear force V(s) integrated over kappa G A):
//     tip load P:     P s / (kappa G A)
//     line load q:    q (L s - s^2 / 2) / (kappa G A)
//   I = b h^3 / 12 (h along the load), A = b h, G = E / (2 (1 + nu)), and the shear
//   correction of a rectangle kappa = 10 (1 + nu) / (12 + 11 nu) (Cowper, J. Appl. Mech. 33,
//   1966), unless given. ../shared/REFERENCES.md: L = 1, 0.1 x 0.1, E = 1e8, nu = 0.3, P = 100
//   gives 0.04 + 3.06e-4 m; gravity (q = rho g A) 0.014715 m.
//
// Units: consistent (N, m, Pa). Valid for w << L; the clamp is the plane s = 0.
#pragma once

namespace stroma::reference {

enum class BeamTheory { eulerBernoulli, timoshenko };

struct CantileverBeam {
  double length = 1;           ///< L
  double height = 0.1;         ///< h, section size along the load
  double width = 0.1;          ///< b, section size across the load
  double youngModulus = 1e8;   ///< E
  double poissonRatio = 0.3;   ///< nu (Timoshenko's shear modulus and kappa)
  double tipForce = 0;         ///< P, total load at the free end, along the deflection
  double lineLoad = 0;         ///< q, load per unit length (gravity: rho g b h)
  double shearCorrection = 0;  ///< kappa; 0: Cowper's rectangle value
  BeamTheory theory = BeamTheory::timoshenko;

  /// True when L, h, b, E > 0, -1 < nu < 0.5, kappa >= 0, all finite.
  bool isValid() const;

  double secondMomentOfArea() const;        ///< I = b h^3 / 12
  double effectiveShearCorrection() const;  ///< kappa, Cowper's when shearCorrection is 0
  /// w(s), deflection along the load at s in [0, L] (s clamped to that range).
  double deflection(double s) const;
  double tipDeflection() const { return deflection(length); }
  /// w'(s), the slope of the deflection curve (Euler-Bernoulli: the section rotation).
  double slope(double s) const;
};

}  // namespace stroma::reference
