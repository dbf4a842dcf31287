// SPDX-License-Identifier: MIT
// The consistency test every force field passes (DESIGN.md section 7, STYLE.md section 9).
//
// A test gives a scene with mechanical states and the force field under test, and says what the
// field is (has an energy, is conservative, is rotation invariant):
//
//   TEST(StiffSpringForceField, PassesTheForceFieldTest) {
//     stroma::test::checkForceField(kSpringScene, {.rotationInvariant = true});
//   }
//
// The positions are moved from the rest shape by a random perturbation (relative to the typical
// spacing of the points), and then, with f the field's force and K = df/dx (the sign
// conventions of simulation/ForceField.h):
//   (a) energy:     f . dx = -(E(x + h dx) - E(x - h dx)) / 2h  along random dx  (hasEnergy)
//   (b) addDForce:  K dx   =  (f(x + h dx) - f(x - h dx)) / 2h, relative error < tolerance
//   (c) matrix:     the field's addKToMatrix times u = its addDForce(u), and the assembled system
//                   matrix (MechanicalOperations::assemble, kFactor 1, mFactor 0) times u = the
//                   matrix-free product (computeMBKdx, projected as assemble projects), for
//                   random u; K symmetric (conservative)
//   (d) rest:       f = 0 at the rest shape (zeroAtRest)
//   (e) rigid:      f = 0 at R rest + t for rotations R and translations t, and at the perturbed
//                   positions the forces sum to zero, as do their moments (rotationInvariant)
//   (f) damping:    B dv (addDForce and addKToMatrix with bFactor 1, kFactor 0) = the central
//                   difference of f in the velocities, about zero velocity (0 = 0 for a field
//                   without damping)
// The step h is fdStep times the typical spacing; a central difference then errs by about
// fdStep^2 relative (truncation, held to `tolerance`) plus eps |f| / (fdStep |K dx|) (round-off,
// estimated at each sample and allowed on top of the tolerance).
//
// measureForceField() returns the measured errors without asserting (to show that a wrong
// field is caught); checkForceField() measures and asserts with GoogleTest.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace stroma {
class Scene;
}

namespace stroma::test {

/// What the field under test is, and how hard to test it.
struct ForceFieldTestOptions {
  /// Path of the force field under test ("/root/FEM"); empty: the scene's only force field
  /// that is not a mass, else its only mass.
  std::string forceField = {};
  /// (a) The field has a potential energy whose gradient is minus its force.
  bool hasEnergy = true;
  /// (c) K is symmetric.
  bool conservative = true;
  /// (d) The force vanishes at the rest shape.
  bool zeroAtRest = true;
  /// (e) The force vanishes under rigid motions of the rest shape, and conserves momentum
  /// (Vec3d and Rigid3d states only: a scene with other states is then a failure).
  bool rotationInvariant = false;
  /// Random displacement of the positions, relative to the typical spacing of the points
  /// (radians for the orientations of rigid frames).
  double perturbation = 0.1;
  /// Finite-difference step, relative to the typical spacing.
  double fdStep = 1e-5;
  /// Relative error allowed for the finite-difference checks (a), (b) and (f).
  double tolerance = 1e-6;
  /// Relative error allowed for (c), (d), (e) and the damping matrix: these hold to round-off.
  double roundOffTolerance = 1e-9;
  /// Number of random directions and vectors for each check.
  int samples = 3;
  unsigned seed = 20240611;
  /// Accept warnings while loading the scene (errors always fail).
  bool allowWarnings = false;
};

/// The measured errors, each relative to the scale named in its comment. A negative value
/// means the check was not run (the option says the field does not have the property).
struct ForceFieldTestReport {
  std::string failure;             ///< non-empty when the test could not run (scene, field)
  std::size_t dofs = 0;            ///< rows of the system
  double spacing = 0;              ///< typical spacing of the points, the length scale
  double forceNorm = 0;            ///< |f| at the perturbed positions, the force scale
  double energyError = -1;         ///< (a) |f.dx + dE/dh| / (|f| |dx|)
  double energyNoise = -1;         ///< (a) round-off of the difference of E, same scale
  double dForceError = -1;         ///< (b) |K dx - FD| / max(|K dx|, |FD|)
  double dForceNoise = -1;         ///< (b) round-off of the difference of f, same scale
  double fieldMatrixError = -1;    ///< (c) |K_assembled u - K u| / |K u|, the field alone
  double systemMatrixError = -1;   ///< (c) |A u - (matrix-free) u| / |A u|, the whole system
  double asymmetry = -1;           ///< (c) |K - K^T| / |K| (Frobenius)
  double dampingError = -1;        ///< (f) |B dv - FD in v| / max(|B dv|, |FD|)
  double dampingNoise = -1;        ///< (f) round-off of that difference, same scale
  double dampingMatrixError = -1;  ///< (f) |B_assembled u - B u| / |B u|
  double restForce = -1;           ///< (d) |f(rest)| / |f(perturbed)|
  double rigidMotionForce = -1;    ///< (e) max |f(R rest + t)| / |f(perturbed)|
  double netForce = -1;            ///< (e) |sum f| / sum |f|, perturbed
  double netMoment = -1;           ///< (e) |sum x x f (+ torques)| / sum |x| |f|, perturbed
  /// One line per measure, for test output.
  std::string describe() const;
};

/// Loads a scene into `scene` (made with a fresh Runtime); returns false on failure. Use it to
/// register components written in the test: `scene.runtime().factory().add(...)`.
using SceneFactory = std::function<bool(Scene& scene)>;

ForceFieldTestReport measureForceField(std::string_view sceneXml,
                                       const ForceFieldTestOptions& options = {});
ForceFieldTestReport measureForceField(const SceneFactory& makeScene,
                                       const ForceFieldTestOptions& options = {});

/// Measures, then asserts each check with GoogleTest (EXPECT, naming the check and the error).
ForceFieldTestReport checkForceField(std::string_view sceneXml,
                                     const ForceFieldTestOptions& options = {});
ForceFieldTestReport checkForceField(const SceneFactory& makeScene,
                                     const ForceFieldTestOptions& options = {});

}  // namespace stroma::test
