// SPDX-License-Identifier: MIT
// The generic force-field test on fields whose answers are known: ConstantForceField (an
// energy, no stiffness), UniformMass (gravity), and a spring field written here; and, to show
// that the test catches what it claims to, springs with one deliberate mistake each.
#include "support/ForceFieldTest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/Runtime.h"
#include "core/Types.h"
#include "simulation/Scene.h"
#include "support/TestSprings.h"

namespace stroma::test {
namespace {

struct SpringsWithoutGeometricStiffness final : TestSprings {
  SpringsWithoutGeometricStiffness() { m_bug = Bug::noGeometricStiffness; }
};
struct SpringsWithWrongMatrixSign final : TestSprings {
  SpringsWithWrongMatrixSign() { m_bug = Bug::matrixSign; }
};
struct SpringsWithWrongEnergy final : TestSprings {
  SpringsWithWrongEnergy() { m_bug = Bug::energyFactor; }
};

/// A cube of 8 points, every pair joined by a spring of class `springClass`, and `extra`
/// components.
SceneFactory springScene(std::string springClass, std::string extra = "") {
  return [springClass, extra](Scene& scene) {
    auto& factory = scene.runtime().factory();
    factory.add("TestSprings", "test").with<CorrectSprings>();
    factory.add("SpringsWithoutGeometricStiffness", "test")
        .with<SpringsWithoutGeometricStiffness>();
    factory.add("SpringsWithWrongMatrixSign", "test").with<SpringsWithWrongMatrixSign>();
    factory.add("SpringsWithWrongEnergy", "test").with<SpringsWithWrongEnergy>();
    std::string edges;
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j < 8; ++j) edges += std::to_string(i) + " " + std::to_string(j) + "  ";
    return scene.loadString(R"(<Node name="root" gravity="0 0 0">
      <MechanicalObject name="dofs" position="0 0 0  2 0 0  0 2 0  2 2 0  0 0 2  2 0 2  0 2 2  2 2 2"/>
      <)" + springClass + R"( name="springs" stiffness="300" edges=")" +
                            edges + R"("/>
      )" + extra + R"(
    </Node>)");
  };
}

TEST(ForceFieldTest, SpringsPassEveryCheck) {
  const auto r = checkForceField(springScene("TestSprings"), {.rotationInvariant = true});
  // Central differences with h = 1e-5 spacing: errors of order 1e-10, far below 1e-6.
  EXPECT_LT(r.dForceError, 1e-8) << r.describe();
  EXPECT_LT(r.energyError, 1e-8) << r.describe();
}

TEST(ForceFieldTest, SpringsWithAFixedPointAndAMass) {
  // The system matrix has the identity at the fixed rows; the mass adds nothing with mFactor 0.
  checkForceField(springScene("TestSprings", R"(<FixedProjectiveConstraint indices="0 5"/>
                                               <UniformMass totalMass="2"/>)"),
                  {.forceField = "/root/springs", .rotationInvariant = true});
}

TEST(ForceFieldTest, ConstantForceFieldHasAnEnergyAndNoStiffness) {
  checkForceField(R"(<Node name="root">
      <MechanicalObject position="0 0 0  1 0 0  0 1 0"/>
      <ConstantForceField indices="0 2" forces="1 2 3  -4 5 6"/>
    </Node>)",
                  {.zeroAtRest = false});
}

TEST(ForceFieldTest, UniformMassGravityIsMinusTheGradientOfItsEnergy) {
  checkForceField(R"(<Node name="root" gravity="0 -9.81 1">
      <MechanicalObject position="0 0 0  1 0 0  0 1 0  3 1 2"/>
      <UniformMass totalMass="4"/>
    </Node>)",
                  {.zeroAtRest = false});
}

TEST(ForceFieldTest, DampedSpringsOfTheSpringPlugin) {
  // Every pair of the unit cube's corners, rest length their distance, stiffness 100 and
  // damping 5: the damping check (f) compares B = kd e e^T with the velocity derivative.
  const Vec3d corners[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  std::ostringstream springs;
  springs.precision(17);
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      springs << i << ' ' << j << " 100 5 " << (corners[j] - corners[i]).norm() << "  ";
  const auto r = checkForceField(R"(<Node name="root" gravity="0 0 0">
      <MechanicalObject position="0 0 0  1 0 0  0 1 0  1 1 0  0 0 1  1 0 1  0 1 1  1 1 1"/>
      <SpringForceField spring=")" + springs.str() +
                                     R"("/>
    </Node>)",
                                 {.rotationInvariant = true});
  EXPECT_LT(r.dampingError, 1e-8) << r.describe();
}

TEST(ForceFieldTest, CatchesAMissingGeometricStiffness) {
  const auto r = measureForceField(springScene("SpringsWithoutGeometricStiffness"));
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_GT(r.dForceError, 1e-3) << r.describe();
  EXPECT_LT(r.fieldMatrixError, 1e-12) << r.describe();  // consistently wrong
}

TEST(ForceFieldTest, CatchesAMatrixThatDisagreesWithAddDForce) {
  const auto r = measureForceField(springScene("SpringsWithWrongMatrixSign"));
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_NEAR(r.fieldMatrixError, 2.0, 1e-9) << r.describe();  // |-Ku - Ku| / |Ku|
  EXPECT_GT(r.systemMatrixError, 1.0) << r.describe();
  EXPECT_LT(r.dForceError, 1e-8) << r.describe();
}

TEST(ForceFieldTest, CatchesAnEnergyThatIsNotTheForcePotential) {
  const auto r = measureForceField(springScene("SpringsWithWrongEnergy"));
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_GT(r.energyError, 1e-3) << r.describe();
}

TEST(ForceFieldTest, CatchesAFieldThatIsNotRotationInvariant) {
  // Constant forces are not zero at rest, and do not balance.
  const auto r = measureForceField(R"(<Node name="root">
      <MechanicalObject position="0 0 0  1 0 0  0 1 0"/>
      <ConstantForceField force="0 0 1"/>
    </Node>)",
                                   {.rotationInvariant = true});
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_GT(r.restForce, 0.5) << r.describe();
  EXPECT_GT(r.rigidMotionForce, 0.5) << r.describe();
  EXPECT_NEAR(r.netForce, 1.0, 1e-12) << r.describe();
}

TEST(ForceFieldTest, ReportsAnAmbiguousOrBrokenScene) {
  auto r = measureForceField(R"(<Node name="root">
      <MechanicalObject position="0 0 0"/>
      <ConstantForceField force="0 0 1"/>
      <ConstantForceField force="0 1 0"/>
    </Node>)");
  EXPECT_NE(r.failure.find("2 force fields"), std::string::npos) << r.failure;
  r = measureForceField(R"(<Node name="root"><MechanicalObject position="0 0 0"/>
      <ConstantForceField indices="3" force="0 0 1"/></Node>)");
  EXPECT_NE(r.failure.find("did not load"), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("out of range"), std::string::npos) << r.failure;
}

}  // namespace
}  // namespace stroma::test
