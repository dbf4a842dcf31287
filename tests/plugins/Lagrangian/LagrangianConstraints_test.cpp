// SPDX-License-Identifier: MIT
// FreeMotionAnimationLoop with bilateral constraints (plugins/Lagrangian): a point held to a
// fixed anchor under gravity stays there and its multiplier is its weight, for each constraint
// correction and time integrator; rigid frames held together keep their relative pose; bad
// input is an error naming the component and field.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(Lagrangian, FixedLagrangianConstraintHoldsPointsAndTellsTheForce) {
  // The hanging chain of HeldPoint with point 0 held where it starts by FixedLagrangianConstraint:
  // it stays there; at rest its holding force carries both weights. A spinning frame held
  // (Rigid3d) keeps its place and orientation.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <FreeMotionAnimationLoop/><GenericConstraintSolver tolerance="1e-12" maxIterations="100"/>
  <Node name="Mass"><EulerImplicitSolver rayleighMass="2"/><SparseLDLSolver/>
    <MechanicalObject name="dofs" position="0 1 0  0.3 1 0"/>
    <UniformMass vertexMass="0.5"/>
    <SpringForceField spring="0 1 200 0 0.3"/>
    <FixedLagrangianConstraint name="hold" indices="0"/>
    <LinearSolverConstraintCorrection/>
  </Node>
  <Node name="Frame"><EulerImplicitSolver/><SparseLDLSolver/>
    <MechanicalObject template="Rigid3d" name="frame" position="1 2 3  0 0 0.258819 0.965926"
                      velocity="0.5 0 0  1 2 3"/>
    <UniformMass vertexMass="2 1 0.1 0 0 0 0.2 0 0 0 0.3"/>
    <FixedLagrangianConstraint template="Rigid3d" fixAll="1"/>
    <UncoupledConstraintCorrection/>
  </Node>
</Node>)")) << describe(scene.log());
  auto& mass = *scene.root().findChild("Mass")->get<MechanicalState<Vec3Types>>();
  for (int n = 0; n < 800; ++n) {
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    ASSERT_LT((mass.readCoord(VecId::position())[0] - Vec3d(0, 1, 0)).norm(), 1e-9) << "step " << n;
  }
  const auto* forces = dynamic_cast<const Data<std::vector<Vec3d>>*>(
      scene.root().findChild("Mass")->findObject("hold")->findData("forces"));
  ASSERT_NE(forces, nullptr);
  ASSERT_EQ(forces->value().size(), 1u);
  EXPECT_NEAR(forces->value()[0].y(), 9.81, 1e-3);
  const RigidCoord3& x =
      scene.root().findChild("Frame")->get<MechanicalState<Rigid3Types>>()->readCoord(VecId::position())[0];
  EXPECT_LT((x.center - Vec3d(1, 2, 3)).norm(), 1e-8);
  EXPECT_LT(x.orientation.angularDistance(Quat(0.965926, 0, 0, 0.258819).normalized()), 1e-6);
}

TEST(Lagrangian, ABeadSlidesDownItsWireAndStopsAtTheEnd) {
  // A 0.2 kg bead on a fixed straight wire from (0, 1, 0) to (1, 0, 0) (45 degrees), frictionless:
  // it stays on the wire and slides with a = g sin 45 (implicit Euler: a h^2 n (n + 1) / 2 after n
  // steps), then rests against the lower end, where the stop carries its weight.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root" dt="0.001" gravity="0 -9.81 0">
  <FreeMotionAnimationLoop/><GenericConstraintSolver tolerance="1e-14" maxIterations="100"/>
  <Node name="Wire"><MechanicalObject name="ends" position="0 1 0  1 0 0"/></Node>
  <Node name="Bead"><EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
    <CGLinearSolver iterations="10" tolerance="1e-20" threshold="1e-30"/>
    <MechanicalObject name="dofs" position="0.1 0.9 0"/>
    <UniformMass vertexMass="0.2"/>
    <UncoupledConstraintCorrection/>
  </Node>
  <SlidingLagrangianConstraint name="wire" object1="@Bead/dofs" object2="@Wire/ends"
      sliding_point="0" axis_1="0" axis_2="1"/>
</Node>)")) << describe(scene.log());
  const auto& bead = *scene.root().findChild("Bead")->get<MechanicalState<Vec3Types>>();
  const Vec3d start(0.1, 0.9, 0), dir = Vec3d(1, -1, 0).normalized();
  const double a = 9.81 * std::sqrt(0.5), h = 1e-3;
  for (int n = 1; n <= 300; ++n) {
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    const Vec3d d = bead.readCoord(VecId::position())[0] - start;
    ASSERT_LT((d - d.dot(dir) * dir).norm(), 1e-10) << "left the wire at step " << n;
    ASSERT_NEAR(d.dot(dir), a * h * h * n * (n + 1) / 2, 1e-9) << "step " << n;
  }
  for (int n = 0; n < 3000; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  EXPECT_LT((bead.readCoord(VecId::position())[0] - Vec3d(1, 0, 0)).norm(), 1e-9);
  const auto* force =
      dynamic_cast<const Data<Vec3d>*>(scene.root().findObject("wire")->findData("force"));
  ASSERT_NE(force, nullptr);
  EXPECT_LT((force->value() - Vec3d(0, 0.2 * 9.81, 0)).norm(), 1e-6) << force->value().transpose();
}

TEST(Lagrangian, AUnilateralConstraintPushesOnlyWhileTouchingAndBrakesBySlidingFriction) {
  // Point 1 falls onto point 0 (fixed) along y: it stops at contactDistance 0.1 above it, pushed
  // by its weight; it never pulls (started 0.05 above the limit, it falls freely until touching).
  // Sliding at 1 m/s along x with mu = 0.5, it brakes at mu g once landed.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root" dt="0.001" gravity="0 -9.81 0">
  <FreeMotionAnimationLoop/><GenericConstraintSolver tolerance="1e-14" maxIterations="100"/>
  <Node name="Ground"><MechanicalObject name="dofs" position="0 0 0"/></Node>
  <Node name="Body"><EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
    <CGLinearSolver iterations="10" tolerance="1e-20" threshold="1e-30"/>
    <MechanicalObject name="dofs" position="0 0.15 0" velocity="1 0 0"/>
    <UniformMass vertexMass="2"/>
    <UncoupledConstraintCorrection/>
  </Node>
  <UnilateralLagrangianConstraint name="contact" object1="@Ground/dofs" object2="@Body/dofs"
      first_point="0" second_point="0" normal="0 2 0" contactDistance="0.1" mu="0.5"/>
</Node>)")) << describe(scene.log());
  const auto& body = *scene.root().findChild("Body")->get<MechanicalState<Vec3Types>>();
  const auto* forces = dynamic_cast<const Data<std::vector<Vec3d>>*>(
      scene.root().findObject("contact")->findData("forces"));
  ASSERT_NE(forces, nullptr);
  double lastVx = 1;
  int touching = 0;
  for (int n = 1; n <= 150; ++n) {
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    const Vec3d& x = body.readCoord(VecId::position())[0];
    const Vec3d& v = body.readDeriv(VecId::velocity())[0];
    ASSERT_GE(x.y(), 0.1 - 1e-12) << "step " << n;
    ASSERT_GE(forces->value().at(0).y(), -1e-12) << "pulled at step " << n;
    if (forces->value()[0].y() > 0) {
      ++touching;
      EXPECT_NEAR(x.y(), 0.1, 1e-12);
      // The landing takes two steps (the first stops the point at the limit with the velocity
      // of its remaining penetration only; the second, the rest); then it slides at rest on y.
      if (touching > 2) {
        EXPECT_NEAR(lastVx - v.x(), 0.5 * 9.81 * 1e-3, 1e-9) << "step " << n;
      }
    } else {
      EXPECT_NEAR(v.x(), 1.0, 1e-12) << "braked before touching, step " << n;
    }
    lastVx = v.x();
  }
  EXPECT_GT(touching, 40);
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
  EXPECT_TRUE(hasError(scene.log(), c.path, c.field, c.text))
      << c.what << ":\n" << describe(scene.log());
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
                           "/root/A/hold", "first_point", "1 index out of range of the 1 points: 1"},
        BadLagrangianInput{"fixed indices out of range",
                           R"(<Node name="root"><FreeMotionAnimationLoop/><GenericConstraintSolver/>
                              <MechanicalObject position="0 0 0"/>
                              <FixedLagrangianConstraint name="fix" indices="3"/></Node>)",
                           "/root/fix", "indices", "1 index out of range of the 1 points: 3"},
        BadLagrangianInput{"a sliding axis of zero length",
                           R"(<Node name="root"><FreeMotionAnimationLoop/><GenericConstraintSolver/>
                              <MechanicalObject position="0 0 0  1 1 1"/>
                              <SlidingLagrangianConstraint name="slide" sliding_point="0" axis_1="1" axis_2="1"/></Node>)",
                           "/root/slide", "axis_2", "no axis to slide along"},
        BadLagrangianInput{"a unilateral constraint without a direction",
                           R"(<Node name="root"><FreeMotionAnimationLoop/><GenericConstraintSolver/>
                              <MechanicalObject position="0 0 0  1 1 1"/>
                              <UnilateralLagrangianConstraint name="push" first_point="0" second_point="1" normal="0 0 0"/></Node>)",
                           "/root/push", "normal", "non-zero direction"},
        BadLagrangianInput{"a negative friction coefficient of a unilateral constraint",
                           R"(<Node name="root"><FreeMotionAnimationLoop/><GenericConstraintSolver/>
                              <MechanicalObject position="0 0 0  1 1 1"/>
                              <UnilateralLagrangianConstraint name="push" first_point="0" second_point="1" mu="-1"/></Node>)",
                           "/root/push", "mu", ""},
        BadLagrangianInput{"an unknown resolution method",
                           R"(<Node name="root"><FreeMotionAnimationLoop/><GenericConstraintSolver name="solver" resolutionMethod="Jacobi"/></Node>)",
                           "/root/solver", "resolutionMethod", "is not one of"},
        BadLagrangianInput{"a mouse button that does not exist",
                           R"(<Node name="root"><AttachBodyButtonSetting name="mouse" button="Fourth"/></Node>)",
                           "/root/mouse", "button", "expected Left, Middle or Right"}),
    NameFromWhat());

}  // namespace
}  // namespace stroma::test
