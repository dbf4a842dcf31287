// SPDX-License-Identifier: MIT
// FreeMotionAnimationLoop with bilateral constraints (plugins/Lagrangian): a point held to a
// fixed anchor under gravity stays there and its multiplier is its weight, for each constraint
// correction and time integrator; rigid frames held together keep their relative pose; bad
// input is an error naming the component and field.
#include <gtest/gtest.h>

#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"
#include "support/TestNames.h"

namespace stroma::test {
namespace {

struct HeldPointCase {
  const char* what;
  std::string solvers;  ///< the ODE solver, linear solver and correction of the mass's node
  bool damped;          ///< the chain comes to rest (else it swings on)
};
void PrintTo(const HeldPointCase& c, std::ostream* out) { *out << c.what; }

std::string heldPoint(const std::string& solvers, const std::string& constraintSolver) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <FreeMotionAnimationLoop/>
  )" + constraintSolver + R"(
  <Node name="Anchor"><MechanicalObject name="dofs" position="0 1 0"/></Node>
  <Node name="Mass">)" + solvers + R"(
    <MechanicalObject name="dofs" position="0 1 0  0.3 1 0"/>
    <UniformMass vertexMass="0.5"/>
    <SpringForceField spring="0 1 200 0 0.3"/>
  </Node>
  <BilateralLagrangianConstraint name="hold" template="Vec3d" object1="@Anchor" object2="@Mass"
                                 first_point="0" second_point="0"/>
</Node>)";
}

class HeldPoint : public ::testing::TestWithParam<HeldPointCase> {};

TEST_P(HeldPoint, StaysAtItsAnchorAndCarriesTheWeightOfTheChain) {
  // Point 0 (0.5 kg) held at the anchor; point 1 (0.5 kg) hangs from it on a spring (k = 200
  // N/m, rest length 0.3 m) and swings down. Point 0 stays at the anchor to the solver's
  // tolerance at every step. Damped, the chain comes to rest and the multiplier on point 0
  // carries both weights, 9.81 N up; undamped (symplectic Euler), the multiplier balances the
  // forces on point 0 at the step's start (its weight and the spring's pull), as point 0 does
  // not move.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(
      heldPoint(GetParam().solvers, R"(<GenericConstraintSolver tolerance="1e-12" maxIterations="100"/>)")))
      << describe(scene.log());
  auto& mass = *scene.root().children()[1]->get<MechanicalState<Vec3Types>>();
  std::vector<Vec3d> before;
  for (int n = 0; n < 800; ++n) {
    before = mass.readCoord(VecId::position());
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    EXPECT_LT((mass.readCoord(VecId::position())[0] - Vec3d(0, 1, 0)).norm(), 1e-9) << "step " << n;
  }
  const auto* forces = dynamic_cast<const Data<std::vector<Vec3d>>*>(
      scene.root().findObject("hold")->findData("forces"));
  ASSERT_NE(forces, nullptr);
  ASSERT_EQ(forces->value().size(), 1u);
  const Vec3d& lambda = forces->value()[0];
  if (GetParam().damped) {
    EXPECT_NEAR(lambda.y(), 2 * 0.5 * 9.81, 1e-3) << lambda.transpose();
    EXPECT_NEAR(lambda.x(), 0, 1e-3);
  } else {
    const Vec3d u = before[1] - before[0];
    const Vec3d spring = 200 * (u.norm() - 0.3) * u.normalized();  // on point 0, towards 1
    const Vec3d balance = -(Vec3d(0, -0.5 * 9.81, 0) + spring);
    EXPECT_LT((lambda - balance).norm(), 1e-9 * balance.norm()) << lambda.transpose() << " / "
                                                                   << balance.transpose();
  }
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << describe(scene.log());
}

INSTANTIATE_TEST_SUITE_P(
    Lagrangian, HeldPoint,
    ::testing::Values(
        HeldPointCase{"implicit Euler with the linear solver's compliance",
                      R"(<EulerImplicitSolver rayleighMass="2"/><SparseLDLSolver/>
                         <LinearSolverConstraintCorrection/>)",
                      true},
        HeldPointCase{"implicit Euler with CG and the linear solver's compliance",
                      R"(<EulerImplicitSolver rayleighMass="2"/>
                         <CGLinearSolver iterations="100" tolerance="1e-14" threshold="1e-30"/>
                         <GenericConstraintCorrection/>)",
                      true},
        HeldPointCase{"symplectic Euler with the uncoupled compliance",
                      R"(<EulerExplicitSolver/><UncoupledConstraintCorrection/>)", false}),
    NameFromWhat());

TEST(Lagrangian, RigidFramesHeldTogetherKeepTheirPose) {
  // A free rigid frame (spinning, falling) held to a fixed frame with keepOrientationDifference:
  // it keeps its position and its orientation offset of 30 degrees about z.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <FreeMotionAnimationLoop/><GenericConstraintSolver tolerance="1e-12" maxIterations="100"/>
  <Node name="Fixed"><MechanicalObject template="Rigid3d" name="frame" position="1 2 3  0 0 0 1"/></Node>
  <Node name="Body"><EulerImplicitSolver/><SparseLDLSolver/>
    <MechanicalObject template="Rigid3d" name="frame" position="1 2 3  0 0 0.258819 0.965926"
                      velocity="0.5 0 0  1 2 3"/>
    <UniformMass vertexMass="2 1 0.1 0 0 0 0.2 0 0 0 0.3"/>
    <LinearSolverConstraintCorrection/>
  </Node>
  <BilateralLagrangianConstraint template="Rigid3d" object1="@Fixed" object2="@Body"
      first_point="0" second_point="0" keepOrientationDifference="1"/>
</Node>)")) << describe(scene.log());
  for (int n = 0; n < 100; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  const RigidCoord3& x =
      scene.root().children()[1]->get<MechanicalState<Rigid3Types>>()->readCoord(VecId::position())[0];
  EXPECT_LT((x.center - Vec3d(1, 2, 3)).norm(), 1e-8);
  const Quat expected(Eigen::AngleAxisd(M_PI / 6, Vec3d::UnitZ()));
  EXPECT_LT(x.orientation.angularDistance(expected), 1e-6);
}

struct BadLagrangianInput {
  const char* what;
  std::string xml;
  const char* path;
  const char* field;
  const char* text;
};
void PrintTo(const BadLagrangianInput& c, std::ostream* out) { *out << c.what; }

class LagrangianBadInput : public ::testing::TestWithParam<BadLagrangianInput> {};

TEST_P(LagrangianBadInput, IsAnErrorNamingTheComponentAndField) {
  const BadLagrangianInput& c = GetParam();
  Runtime runtime;
  Scene scene(runtime);
  bool failed = !scene.loadString(c.xml);
  for (int n = 0; n < 2 && !failed; ++n) failed = !scene.step();
  EXPECT_TRUE(failed) << c.what;
  bool found = false;
  for (const Message& m : errors(scene.log()))
    found |= m.componentPath == c.path && m.field == c.field &&
             m.text.find(c.text) != std::string::npos;
  EXPECT_TRUE(found) << c.what << ":\n" << describe(scene.log());
}

INSTANTIATE_TEST_SUITE_P(
    Lagrangian, LagrangianBadInput,
    ::testing::Values(
        BadLagrangianInput{"a constraint solver without FreeMotionAnimationLoop",
                           R"(<Node name="root"><GenericConstraintSolver name="solver"/></Node>)",
                           "/root/solver", "",
                           "only FreeMotionAnimationLoop asks for: add <FreeMotionAnimationLoop/>"},
        BadLagrangianInput{"FreeMotionAnimationLoop without a constraint solver",
                           R"(<Node name="root"><FreeMotionAnimationLoop name="loop"/></Node>)",
                           "/root/loop", "constraintSolver", "needs a constraint solver"},
        BadLagrangianInput{"a constrained body without a constraint correction",
                           heldPoint("<EulerImplicitSolver/><SparseLDLSolver/>",
                                     "<GenericConstraintSolver/>"),
                           "/root/freeMotionAnimationLoop", "constraintSolver",
                           "no constraint correction: add UncoupledConstraintCorrection"},
        BadLagrangianInput{"a negative friction coefficient",
                           R"(<Node name="root"><FreeMotionAnimationLoop/><LCPConstraintSolver name="lcp" mu="-0.1"/></Node>)",
                           "/root/lcp", "mu", ">= 0"},
        BadLagrangianInput{"bilateral indices out of range",
                           R"(<Node name="root"><FreeMotionAnimationLoop/><GenericConstraintSolver/>
                              <Node name="A"><MechanicalObject position="0 0 0"/>
                              <BilateralLagrangianConstraint name="hold" first_point="0 1" second_point="0 0"/></Node></Node>)",
                           "/root/A/hold", "first_point", "point 1 is out of range of the 1 points"}),
    NameFromWhat());

}  // namespace
}  // namespace stroma::test
