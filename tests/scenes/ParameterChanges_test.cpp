// SPDX-License-Identifier: MIT
// Parameters changed while a simulation runs take effect at the next step, without a manual
// re-initialization: gravity and the time step of the root node, a mass, a constraint's
// indices (directly, or through the BoxROI they are linked to), a force. Each change is
// checked against the exact symplectic Euler update v += dt F / m, x += dt v.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "core/Data.h"
#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

// Three free points of 2 kg (the first one fixed), a 1 N force on the third, gravity -10 y.
const char* kParticles = R"(<Node name="root" dt="0.01" gravity="0 -10 0">
  <Node name="Body">
    <EulerExplicitSolver symplectic="true"/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0"/>
    <UniformMass name="mass" vertexMass="2"/>
    <BoxROI name="box" box="-0.5 -0.5 -0.5  0.5 0.5 0.5" position="@dofs.rest_position"/>
    <FixedConstraint name="fixed" indices="@box.indices"/>
    <ConstantForceField name="push" indices="2" forces="1 0 0"/>
  </Node>
</Node>)";

class ParameterChanges : public ::testing::Test {
 protected:
  void SetUp() override {
    scene = std::make_unique<Scene>(runtime);
    ASSERT_TRUE(scene->loadString(kParticles)) << describe(scene->log());
    std::string why;
    dofs = dynamic_cast<MechanicalState<Vec3Types>*>(
        resolveObjectPath(scene->root(), "@/Body/dofs", why));
    ASSERT_NE(dofs, nullptr) << why;
  }

  void set(const std::string& dataPath, const std::string& value) {
    std::string why;
    BaseData* data = resolveDataPath(scene->root(), dataPath, why);
    ASSERT_NE(data, nullptr) << dataPath << ": " << why;
    ASSERT_TRUE(data->read(value, why)) << dataPath << " = " << value << ": " << why;
  }

  /// One step; checks v_new = v_old + dt a for every point (a = 0 for the fixed ones, whose
  /// positions must not change) and x_new = x_old + dt v_new.
  void stepAndExpect(double dt, const std::vector<Vec3d>& acceleration) {
    const std::vector<Vec3d> x0 = dofs->readCoord(VecId::position());
    const std::vector<Vec3d> v0 = dofs->readDeriv(VecId::velocity());
    const double t0 = scene->root().time();
    ASSERT_TRUE(scene->step()) << describe(scene->log());
    EXPECT_NEAR(scene->root().time(), t0 + dt, 1e-15);
    const std::vector<Vec3d> x = dofs->readCoord(VecId::position());
    const std::vector<Vec3d> v = dofs->readDeriv(VecId::velocity());
    for (std::size_t i = 0; i < x.size(); ++i) {
      SCOPED_TRACE("point " + std::to_string(i));
      const bool fixed = acceleration[i].hasNaN();
      const Vec3d expectedV = fixed ? Vec3d::Zero() : Vec3d(v0[i] + dt * acceleration[i]);
      EXPECT_LT((v[i] - expectedV).norm(), 1e-14) << v[i].transpose();
      const Vec3d expectedX = fixed ? x0[i] : Vec3d(x0[i] + dt * expectedV);
      EXPECT_LT((x[i] - expectedX).norm(), 1e-14) << x[i].transpose();
    }
    EXPECT_EQ(scene->log().count(MessageLevel::warning), 0u) << describe(scene->log());
  }

  static Vec3d heldPoint() { return Vec3d::Constant(std::nan("")); }

  Runtime runtime;
  std::unique_ptr<Scene> scene;
  MechanicalState<Vec3Types>* dofs = nullptr;
};

TEST_F(ParameterChanges, GravityAndTimeStepOfTheRootNode) {
  const Vec3d g(0, -10, 0), push(0.5, 0, 0);  // push: 1 N on 2 kg
  stepAndExpect(0.01, {heldPoint(), g, g + push});
  set("@/root.gravity", "5 0 0");
  const Vec3d g2(5, 0, 0);
  stepAndExpect(0.01, {heldPoint(), g2, g2 + push});
  set("@/root.dt", "0.02");
  stepAndExpect(0.02, {heldPoint(), g2, g2 + push});
}

TEST_F(ParameterChanges, MassAndForce) {
  set("@/Body/mass.vertexMass", "4");
  const Vec3d g(0, -10, 0);
  stepAndExpect(0.01, {heldPoint(), g, g + Vec3d(0.25, 0, 0)});  // 1 N on 4 kg
  set("@/Body/push.forces", "0 8 0");
  stepAndExpect(0.01, {heldPoint(), g, g + Vec3d(0, 2, 0)});
  set("@/Body/mass.totalMass", "3");  // 1 kg per point
  stepAndExpect(0.01, {heldPoint(), g, g + Vec3d(0, 8, 0)});
}

TEST_F(ParameterChanges, ConstraintIndicesDirectlyOrThroughTheirBox) {
  const Vec3d g(0, -10, 0), push(0.5, 0, 0);
  stepAndExpect(0.01, {heldPoint(), g, g + push});
  // The box moves to the second point: the linked indices follow at the next step.
  set("@/Body/box.box", "0.5 -0.5 -0.5  1.5 0.5 0.5");
  stepAndExpect(0.01, {g, heldPoint(), g + push});
  // Indices given directly (the link to the box is replaced by a value).
  set("@/Body/fixed.indices", "0 2");
  stepAndExpect(0.01, {heldPoint(), g, heldPoint()});
}

TEST_F(ParameterChanges, AnOutOfRangeIndexIsReportedAtTheNextStep) {
  set("@/Body/fixed.indices", "1 7");
  scene->step();
  const Message m = findError(scene->log(), "7");
  EXPECT_EQ(m.componentPath, "/root/Body/fixed") << describe(scene->log());
  EXPECT_EQ(m.field, "indices") << describe(scene->log());
}

}  // namespace
}  // namespace stroma::test
