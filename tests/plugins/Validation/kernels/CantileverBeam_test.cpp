// SPDX-License-Identifier: MIT
// Cantilever deflections against ../shared/REFERENCES.md, Timoshenko -> Euler-Bernoulli for
// slender beams, and the deflection curve against its slope by finite differences.
#include "Validation/kernels/CantileverBeam.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stroma::reference {
namespace {

CantileverBeam referenceBeam() {
  CantileverBeam b;  // L = 1, 0.1 x 0.1, E = 1e8, nu = 0.3
  b.tipForce = 100;
  return b;
}

TEST(CantileverBeam, TipLoadMatchesReferenceValues) {
  CantileverBeam b = referenceBeam();
  EXPECT_NEAR(b.secondMomentOfArea(), 8.3333333e-6, 1e-12);
  EXPECT_NEAR(b.effectiveShearCorrection(), 0.8497, 1e-4);
  b.theory = BeamTheory::eulerBernoulli;
  EXPECT_NEAR(b.tipDeflection(), 0.04, 1e-12);
  b.theory = BeamTheory::timoshenko;
  // Shear: P L / (kappa G A) = 100 / (0.8497 * 3.846e7 * 0.01) = 3.06e-4.
  EXPECT_NEAR(b.tipDeflection() - 0.04, 3.06e-4, 1e-6);
}

TEST(CantileverBeam, GravityLoadMatchesReferenceValue) {
  CantileverBeam b;
  b.theory = BeamTheory::eulerBernoulli;
  b.lineLoad = 1000 * 9.81 * 0.01;  // rho g A
  EXPECT_NEAR(b.tipDeflection(), 0.014715, 1e-9);
}

TEST(CantileverBeam, TimoshenkoTendsToEulerBernoulliForSlenderBeams) {
  // The shear part over the bending part is 3 E I / (kappa G A L^2) ~ (h / L)^2: divided by
  // 100 each time the slenderness grows tenfold.
  double previous = 0;
  for (double L : {1.0, 10.0, 100.0}) {
    CantileverBeam b = referenceBeam();
    b.length = L;
    const double timoshenko = b.tipDeflection();
    b.theory = BeamTheory::eulerBernoulli;
    const double relative = timoshenko / b.tipDeflection() - 1;
    EXPECT_GT(relative, 0);
    if (previous > 0) {
      EXPECT_NEAR(relative / previous, 0.01, 1e-12);
    }
    previous = relative;
  }
  EXPECT_LT(previous, 1e-6);
}

TEST(CantileverBeam, CurveIsClampedAndItsSlopeIsTheDerivative) {
  for (BeamTheory theory : {BeamTheory::eulerBernoulli, BeamTheory::timoshenko}) {
    CantileverBeam b = referenceBeam();
    b.lineLoad = 50;
    b.theory = theory;
    EXPECT_EQ(b.deflection(0), 0);
    const double h = 1e-5;
    for (double s : {0.1, 0.4, 0.7, 0.95}) {
      const double fd = (b.deflection(s + h) - b.deflection(s - h)) / (2 * h);
      EXPECT_NEAR(b.slope(s), fd, 1e-9 * b.tipDeflection());
    }
    // Euler-Bernoulli's curvature is the bending moment over EI: M(s) = P (L - s) + q (L -
    // s)^2 / 2, by finite differences of the slope.
    if (theory == BeamTheory::eulerBernoulli) {
      const double EI = b.youngModulus * b.secondMomentOfArea();
      for (double s : {0.2, 0.5, 0.8}) {
        const double curvature = (b.slope(s + h) - b.slope(s - h)) / (2 * h);
        const double M = b.tipForce * (1 - s) + b.lineLoad * (1 - s) * (1 - s) / 2;
        EXPECT_NEAR(curvature, M / EI, 1e-8 * M / EI);
      }
    }
  }
}

TEST(CantileverBeam, ValidityRange) {
  CantileverBeam b = referenceBeam();
  EXPECT_TRUE(b.isValid());
  b.height = 0;
  EXPECT_FALSE(b.isValid());
  b = referenceBeam();
  b.poissonRatio = 0.5;
  EXPECT_FALSE(b.isValid());
  b = referenceBeam();
  b.tipForce = std::nan("");
  EXPECT_FALSE(b.isValid());
}

}  // namespace
}  // namespace stroma::reference
