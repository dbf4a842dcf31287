// SPDX-License-Identifier: MIT
// The test force fields of TestSprings.h pass the generic force-field test: the physics tests
// of the solvers rest on forces, K and energies that agree.
#include "TestSprings.h"
#include "core/Runtime.h"

#include <gtest/gtest.h>

#include "simulation/Scene.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

SceneFactory withTestSprings(const std::string& xml) {
  return [xml](Scene& scene) {
    registerTestSprings(scene.runtime().factory());
    return scene.loadString(xml);
  };
}

const char* kPoints = R"(position="0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0.5 1")";

TEST(TestAnchorForceField, PassesTheForceFieldTest) {
  checkForceField(withTestSprings(std::string(R"(<Node name="root" gravity="0 0 0">
  <MechanicalObject )") + kPoints +
                                  R"(/>
  <TestAnchorForceField stiffness="3 50 700" cubicStiffness="20"/>
</Node>)"));
}

TEST(TestSpringForceField, PassesTheForceFieldTest) {
  checkForceField(withTestSprings(std::string(R"(<Node name="root" gravity="0 0 0">
  <MechanicalObject )") + kPoints +
                                  R"(/>
  <TestSpringForceField springs="0 1  1 2  2 3  3 0  0 4  1 5  4 5  2 5" stiffness="40"
                        cubicStiffness="300"/>
</Node>)"),
                  {.rotationInvariant = true});
}

}  // namespace
}  // namespace stroma::test
