// SPDX-License-Identifier: MIT
#include "MouseSpringForceField.h"

#include <gtest/gtest.h>

#include "core/Runtime.h"
#include "simulation/Scene.h"
#include "support/ForceFieldTest.h"

namespace stroma {
namespace {

// Four points, the spring on the third, its target away from it: no energy at rest, since the
// spring is not elastic about the rest shape.
test::SceneFactory springScene(const std::string& solvers = "") {
  return [solvers](Scene& scene) {
    scene.runtime().factory().add("MouseSpringForceField", "test").with<MouseSpringForceField>(
        "Vec3d");
    return scene.loadString(R"(<Node name="root" gravity="0 0 0">)" + solvers + R"(
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
      <MouseSpringForceField name="spring" index="2" target="0.3 1.4 -0.2" stiffness="250"/>
    </Node>)");
  };
}

TEST(MouseSpringForceField, PassesTheForceFieldTest) {
  test::checkForceField(springScene(), {.zeroAtRest = false});
}

TEST(MouseSpringForceField, PullsItsPointTowardTheTargetWithForceKTimesTheGap) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(springScene()(scene));
  auto* spring = dynamic_cast<MouseSpringForceField*>(scene.root().findObject("spring"));
  ASSERT_NE(spring, nullptr);
  std::vector<Vec3d> f(4, Vec3d::Zero());
  const std::vector<Vec3d> x = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)};
  spring->addForce({}, f, x, std::vector<Vec3d>(4, Vec3d::Zero()));
  // k (t - x_2) = 250 (0.3, 0.4, -0.2); the other points feel nothing.
  EXPECT_TRUE(f[2].isApprox(Vec3d(75, 100, -50), 1e-12)) << f[2].transpose();
  EXPECT_EQ(f[0].norm() + f[1].norm() + f[3].norm(), 0.0);
}

TEST(MouseSpringForceField, AnIndexPastTheStateIsAnError) {
  Runtime runtime;
  Scene scene(runtime);
  scene.runtime().factory().add("MouseSpringForceField", "test").with<MouseSpringForceField>(
      "Vec3d");
  EXPECT_FALSE(scene.loadString(R"(<Node name="root">
      <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
      <MouseSpringForceField name="spring" index="5"/>
    </Node>)"));
  EXPECT_GE(scene.log().errorCount(), 1u);
}

}  // namespace
}  // namespace stroma
