// SPDX-License-Identifier: MIT
// Lame's thick cylinder: the values of ../shared/REFERENCES.md, boundary conditions and the
// equilibrium equation by finite differences.
#include "Validation/kernels/LameCylinder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stroma::reference {
namespace {

LameCylinder makeCylinder(double nu) {
  LameCylinder c;
  c.innerRadius = 1;
  c.outerRadius = 2;
  c.pressure = 1e-3;
  c.youngModulus = 1;
  c.poissonRatio = nu;
  return c;
}

TEST(LameCylinder, InnerDisplacementMatchesReferenceValues) {
  // ../shared/REFERENCES.md, "Volumetric locking" (7 significant digits given there).
  EXPECT_NEAR(makeCylinder(0.3).radialDisplacement(1), 1.906667e-3, 1e-9);
  EXPECT_NEAR(makeCylinder(0.49).radialDisplacement(1), 1.996600e-3, 1e-9);
  EXPECT_NEAR(makeCylinder(0.499).radialDisplacement(1), 1.999666e-3, 1e-9);
  EXPECT_NEAR(makeCylinder(0.4999).radialDisplacement(1), 1.999967e-3, 1e-9);
  EXPECT_NEAR(makeCylinder(0.5).radialDisplacement(1), 2.0e-3, 1e-12);
}

TEST(LameCylinder, DisplacementSatisfiesEquilibriumAndBoundaryStresses) {
  for (double nu : {0.0, 0.3, 0.49, 0.4999}) {
    const LameCylinder c = makeCylinder(nu);
    const double E = c.youngModulus;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double mu = E / (2 * (1 + nu));
    const double h = 1e-3;  // truncation O(h^2) ~ 1e-6 u, round-off ~ 1e-13 u
    for (double r : {1.0, 1.25, 1.5, 1.75, 2.0}) {
      const double u = c.radialDisplacement(r);
      const double du = (c.radialDisplacement(r + h) - c.radialDisplacement(r - h)) / (2 * h);
      const double d2u =
          (c.radialDisplacement(r + h) - 2 * u + c.radialDisplacement(r - h)) / (h * h);
      // Navier's equation in plane-strain axisymmetry: u'' + u'/r - u/r^2 = 0.
      EXPECT_NEAR(d2u + du / r - u / (r * r), 0, 1e-5 * std::abs(u)) << "nu " << nu << " r " << r;
      // The stresses multiply u' by lambda (large near nu = 0.5): a finer central difference.
      const double h1 = 1e-6;
      const double du1 = (c.radialDisplacement(r + h1) - c.radialDisplacement(r - h1)) / (2 * h1);
      // Hooke: sigma_rr = (lambda + 2 mu) u' + lambda u / r, sigma_tt = lambda u' + (lambda +
      // 2 mu) u / r; the closed-form stresses must agree (tolerance of the central difference).
      EXPECT_NEAR((lambda + 2 * mu) * du1 + lambda * u / r, c.radialStress(r), 1e-8);
      EXPECT_NEAR(lambda * du1 + (lambda + 2 * mu) * u / r, c.hoopStress(r), 1e-8);
    }
    EXPECT_NEAR(c.radialStress(c.innerRadius), -c.pressure, 1e-15);
    EXPECT_NEAR(c.radialStress(c.outerRadius), 0, 1e-15);
  }
}

TEST(LameCylinder, DisplacementVectorIsRadial) {
  const LameCylinder c = makeCylinder(0.3);
  const Eigen::Vector3d x(0.6, 0.8 * 1.5 / 1.0, 3.0);
  const Eigen::Vector3d u = c.displacement(x);
  const double r = std::hypot(x.x(), x.y());
  EXPECT_NEAR(u.z(), 0, 0);
  EXPECT_NEAR(u.head<2>().norm(), c.radialDisplacement(r), 1e-15);
  EXPECT_NEAR(u.x() * x.y() - u.y() * x.x(), 0, 1e-15);
}

TEST(LameCylinder, ValidityRange) {
  EXPECT_TRUE(makeCylinder(0.5).isValid());
  EXPECT_FALSE(makeCylinder(0.51).isValid());
  LameCylinder c = makeCylinder(0.3);
  c.outerRadius = c.innerRadius;
  EXPECT_FALSE(c.isValid());
  c = makeCylinder(0.3);
  c.youngModulus = 0;
  EXPECT_FALSE(c.isValid());
}

}  // namespace
}  // namespace stroma::reference
