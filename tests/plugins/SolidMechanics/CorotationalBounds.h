// SPDX-License-Identifier: MIT
// The bounds of the generic force-field test (tests/support/ForceFieldTest.h) on the
// corotational FEM force fields, shared by their tests.
#pragma once

#include <gtest/gtest.h>

#include "support/ForceFieldTest.h"

namespace stroma::test {

/// Asserts what the generic force-field test (measureForceField, rotationInvariant, at strains
/// of order p) measures on a corotational FEM field: (a) f = -dE/dx exactly when `exactEnergy`
/// (R^T F symmetric: tetrahedra with polar or svd), to O(p) otherwise (kernels README, "Known
/// limits"); (b) addDForce against central differences to O(p), the dR/dx term left out; (c)
/// the assembled matrix is addDForce, in the field and in the system, and K is symmetric;
/// (d), (e) no force at rest nor under rigid motions, no net force, no net moment when
/// `exactEnergy` and an O(p) one otherwise; (f) no damping: the forces do not depend on the
/// velocities, nor do bFactor products.
inline void expectCorotationalBounds(const ForceFieldTestReport& r, double p, bool exactEnergy) {
  EXPECT_LT(r.energyError, exactEnergy ? 1e-6 : 3 * p) << r.describe();
  EXPECT_LT(r.dForceError, 3 * p) << r.describe();
  EXPECT_LT(r.fieldMatrixError, 1e-12) << r.describe();
  EXPECT_LT(r.systemMatrixError, 1e-12) << r.describe();
  EXPECT_LT(r.asymmetry, 1e-14) << r.describe();
  EXPECT_LT(r.restForce, 1e-10) << r.describe();
  EXPECT_LT(r.rigidMotionForce, 1e-10) << r.describe();
  EXPECT_LT(r.netForce, 1e-12) << r.describe();
  EXPECT_LT(r.netMoment, exactEnergy ? 1e-12 : 3 * p) << r.describe();
  EXPECT_EQ(r.dampingError, 0) << r.describe();
  EXPECT_EQ(r.dampingMatrixError, 0) << r.describe();
}

}  // namespace stroma::test
