// SPDX-License-Identifier: MIT
// Contacts as Lagrangian constraints (CollisionResponse response="FrictionContactConstraint",
// FreeMotionAnimationLoop): Coulomb's law on a slope (a rigid cube sticks below atan(mu), slides
// above with a = g (sin theta - mu cos theta), exactly as implicit Euler integrates it), a rigid
// ball rolls down without slipping (a = 5/7 g sin theta), every solved contact problem meets its
// laws, and bad input is an error naming the component and field.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"
#include "support/TestNames.h"

namespace stroma::test {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1e-3;

std::string text(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

// "x y z qx qy qz qw" of a frame at `c` turned by `angle` about z.
std::string frame(const Vec3d& c, double angle) {
  return text(c.x()) + " " + text(c.y()) + " " + text(c.z()) + " 0 0 " + text(std::sin(angle / 2)) +
         " " + text(std::cos(angle / 2));
}

std::string root(const std::string& solver, const std::string& response, const std::string& body) {
  return R"(<Node name="root" dt=")" + text(kDt) + R"(" gravity="0 -9.81 0">
  <FreeMotionAnimationLoop/>
  )" + solver + R"(
  <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
  <MinProximityIntersection alarmDistance="0.01" contactDistance="0"/>
  )" + response + body + "</Node>";
}

// A fixed slab (half extents 2 x 0.1 x 1) turned by theta about z, its top face through the
// origin's normal line at 0.1.
std::string slope(double theta) {
  return R"(<Node name="Slope"><MechanicalObject template="Rigid3d" position=")" +
         frame(Vec3d::Zero(), theta) +
         R"("/><OBBCollisionModel extents="2 0.1 1" simulated="0" moving="0"/></Node>)";
}

Vec3d upSlope(double theta) { return Vec3d(-std::sin(theta), std::cos(theta), 0); }
Vec3d downSlope(double theta) { return Vec3d(-std::cos(theta), -std::sin(theta), 0); }

// A rigid cube (1 kg, half side 0.1) resting on the slope, turned with it.
std::string cubeOn(double theta, const std::string& correction) {
  const double h = 0.1, j = (2 * h) * (2 * h) / 6;
  const Vec3d c = (0.1 + h) * upSlope(theta);
  return R"(<Node name="Cube"><EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
    <CGLinearSolver iterations="25" tolerance="1e-14" threshold="1e-30"/>
    <MechanicalObject name="dofs" template="Rigid3d" position=")" +
         frame(c, theta) + R"("/>
    <UniformMass vertexMass="1 1 )" + text(j) + " 0 0 0 " + text(j) + " 0 0 0 " + text(j) +
         R"("/><OBBCollisionModel extents="0.1 0.1 0.1"/>)" + correction + "</Node>";
}

const RigidCoord3& frameOf(Scene& scene, const std::string& node) {
  return scene.root().findChild(node)->get<MechanicalState<Rigid3Types>>()->readCoord(
      VecId::position())[0];
}
const RigidDeriv3& velocityOf(Scene& scene, const std::string& node) {
  return scene.root().findChild(node)->get<MechanicalState<Rigid3Types>>()->readDeriv(
      VecId::velocity())[0];
}

struct SlopeCase {
  const char* what;
  double thetaDegrees;
  double mu;
  std::string solver;
  std::string response = "FrictionContactConstraint";
};
void PrintTo(const SlopeCase& c, std::ostream* out) { *out << c.what; }

class CoulombSlope : public ::testing::TestWithParam<SlopeCase> {};

TEST_P(CoulombSlope, SticksBelowTheFrictionAngleAndSlidesAboveIt) {
  // The cube stands on the slope with its bottom face on the slab's top face (4 corner contacts).
  // Sliding, each step implicit Euler gives v_n = a h n and a distance a h^2 n (n + 1) / 2 down the
  // slope, a = g (sin theta - mu cos theta); sticking (tan theta <= mu), it stays where it is.
  // The cube does not turn either way (the friction at each corner is opposite to its slip).
  const SlopeCase& c = GetParam();
  const double theta = c.thetaDegrees * M_PI / 180;
  Runtime runtime;
  Scene scene(runtime);
  const std::string response = R"(<CollisionResponse response=")" + c.response +
                               R"(" responseParams="mu=)" + text(c.mu) + R"("/>)";
  ASSERT_TRUE(scene.loadString(root(c.solver, response,
                                    slope(theta) + cubeOn(theta, "<UncoupledConstraintCorrection/>"))))
      << describe(scene.log());
  const Vec3d start = frameOf(scene, "Cube").center;
  const int steps = 400;
  for (int n = 0; n < steps; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  const bool sticks = c.response == "StickContactConstraint" || std::tan(theta) <= c.mu;
  const double a = sticks ? 0.0 : kG * (std::sin(theta) - c.mu * std::cos(theta));
  const double expectedV = a * kDt * steps;
  const double expectedD = a * kDt * kDt * steps * (steps + 1) / 2;
  const RigidCoord3& x = frameOf(scene, "Cube");
  const RigidDeriv3& v = velocityOf(scene, "Cube");
  const Vec3d moved = x.center - start;
  // Implicit Euler with exact contacts: the discrete motion to the solver's tolerance.
  EXPECT_NEAR(moved.dot(downSlope(theta)), expectedD, 1e-9 + 1e-7 * expectedD);
  EXPECT_NEAR(v.linear.dot(downSlope(theta)), expectedV, 1e-9 + 1e-7 * expectedV);
  EXPECT_LT(std::abs(moved.dot(upSlope(theta))), 1e-9) << "left the slope's surface";
  EXPECT_LT(std::abs(moved.z()), 1e-9) << "drifted sideways";
  EXPECT_LT(v.angular.norm(), 1e-7) << "turned: " << v.angular.transpose();
  // The contact force on the cube (its constraintForce: the force a haptic device would
  // render): m (a - g), and no torque about its centre.
  const auto& force = scene.root().findChild("Cube")->get<MechanicalState<Rigid3Types>>()->readDeriv(
      VecId::constraintForce());
  ASSERT_EQ(force.size(), 1u);
  const Vec3d expectedForce = a * downSlope(theta) - Vec3d(0, -kG, 0);
  EXPECT_LT((force[0].linear - expectedForce).norm(), 1e-6) << force[0].linear.transpose();
  EXPECT_LT(force[0].angular.norm(), 1e-6) << force[0].angular.transpose();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << describe(scene.log());
}

const std::string kGeneric =
    R"(<GenericConstraintSolver maxIterations="1000" tolerance="1e-13"/>)";
const std::string kLcp = R"(<LCPConstraintSolver maxIt="1000" tolerance="1e-13" mu="0.3"/>)";

INSTANTIATE_TEST_SUITE_P(
    Lagrangian, CoulombSlope,
    ::testing::Values(
        SlopeCase{"10 degrees, mu 0.3: sticks", 10, 0.3, kGeneric},
        SlopeCase{"16.5 degrees, mu 0.3 (friction angle 16.7): sticks", 16.5, 0.3, kGeneric},
        SlopeCase{"17 degrees, mu 0.3: slides", 17, 0.3, kGeneric},
        SlopeCase{"30 degrees, mu 0.3: slides", 30, 0.3, kGeneric},
        SlopeCase{"30 degrees, mu 0.3, LCPConstraintSolver: slides", 30, 0.3, kLcp},
        SlopeCase{"45 degrees, frictionless: slides at g sin theta", 45, 0.0, kGeneric},
        SlopeCase{"60 degrees, StickContactConstraint: held", 60, 0.0, kGeneric,
                  "StickContactConstraint"}),
    NameFromWhat());

TEST(ContactConstraint, ABallRollsDownASlopeWithoutSlipping) {
  // A solid ball (m = 1 kg, r = 0.1 m, I = 2/5 m r^2) on a 20 degree slope with mu = 0.5 (above
  // the 2/7 tan theta = 0.10 that rolling needs): friction at its contact point turns it, it
  // rolls with a = 5/7 g sin theta and omega r = v; without friction it slides at g sin theta
  // and does not turn.
  for (const double mu : {0.5, 0.0}) {
    const double theta = 20 * M_PI / 180, r = 0.1, j = 0.4 * r * r;
    const Vec3d c = (0.1 + r) * upSlope(theta);
    const std::string ball = R"(<Node name="Ball"><EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
      <CGLinearSolver iterations="25" tolerance="1e-14" threshold="1e-30"/>
      <MechanicalObject template="Rigid3d" position=")" + frame(c, 0) + R"("/>
      <UniformMass vertexMass="1 1 )" + text(j) + " 0 0 0 " + text(j) + " 0 0 0 " + text(j) +
                             R"("/><SphereCollisionModel template="Rigid3d" radius="0.1"/>
      <UncoupledConstraintCorrection/></Node>)";
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(scene.loadString(root(kGeneric,
                                      R"(<CollisionResponse response="FrictionContactConstraint" responseParams="mu=)" +
                                          text(mu) + R"("/>)",
                                      slope(theta) + ball)))
        << describe(scene.log());
    const int steps = 300;
    for (int n = 0; n < steps; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
    const RigidDeriv3& v = velocityOf(scene, "Ball");
    const double a = (mu > 0 ? 5.0 / 7.0 : 1.0) * kG * std::sin(theta);
    EXPECT_NEAR(v.linear.dot(downSlope(theta)), a * kDt * steps, 1e-7) << "mu " << mu;
    // Rolling: the contact point is at rest, v + omega x (-r n) = 0.
    const Vec3d contactVelocity = v.linear + v.angular.cross(-r * upSlope(theta));
    if (mu > 0)
      EXPECT_LT(contactVelocity.norm(), 1e-8) << "slips: " << contactVelocity.transpose();
    else
      EXPECT_LT(v.angular.norm(), 1e-10) << "turns without friction";
  }
}

// A pile of six cubes dropped on a floor, onto each other, with friction.
std::string pile(const std::string& solver) {
  std::string bodies = R"(<Node name="Floor"><MechanicalObject template="Rigid3d" position="0 -0.1 0 0 0 0 1"/>
    <OBBCollisionModel extents="3 0.1 3" simulated="0" moving="0"/></Node>)";
  const double h = 0.1, j = (2 * h) * (2 * h) / 6;
  for (int i = 0; i < 6; ++i) {
    const Vec3d c(0.07 * (i % 3) - 0.05, 0.11 + 0.25 * i, 0.03 * (i % 2));
    bodies += "<Node name=\"Cube" + std::to_string(i) +
              R"("><EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
      <CGLinearSolver iterations="25" tolerance="1e-14" threshold="1e-30"/>
      <MechanicalObject template="Rigid3d" position=")" + frame(c, 0.2 * i) + R"("/>
      <UniformMass vertexMass="1 1 )" + text(j) + " 0 0 0 " + text(j) + " 0 0 0 " + text(j) +
              R"("/><OBBCollisionModel extents="0.1 0.1 0.1"/><UncoupledConstraintCorrection/></Node>)";
  }
  return root(solver, R"(<CollisionResponse response="FrictionContactConstraint" responseParams="mu=0.4"/>)",
              bodies);
}

TEST(ContactConstraint, EverySolvedProblemMeetsItsLaws) {
  // Each step's problem, checked independently of the solver (lawResiduals): forces push
  // (lambda_n >= 0), nothing penetrates beyond the solver's tolerance (delta_n >= -tol), a force
  // only where the gap is closed (lambda_n delta_n ~ 0), friction inside the cone (|lambda_t| <=
  // mu lambda_n) and no slip where it sticks: within 1e-8 m (the solver stops when a sweep
  // moves no row by more than 1e-10 m; the residual is larger, Gauss-Seidel converging slowly
  // on a pile).
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(
      pile(R"(<GenericConstraintSolver maxIterations="5000" tolerance="1e-10"/>)")))
      << describe(scene.log());
  const auto* solver = scene.root().get<BaseConstraintSolver>();
  ASSERT_NE(solver, nullptr);
  std::size_t problems = 0, largest = 0;
  for (int n = 0; n < 500; ++n) {
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    const ConstraintProblem* p = solver->lastProblem();
    if (!p || p->groups.empty()) continue;
    ++problems;
    largest = std::max(largest, p->groups.size());
    const double scale = std::max(1.0, p->lambda.cwiseAbs().maxCoeff());
    const ConstraintLawResiduals r = lawResiduals(*p);
    EXPECT_LE(r.negativeForce, 0.0) << "step " << n;
    EXPECT_LT(r.penetration, 1e-8) << "step " << n;
    EXPECT_LT(r.complementarity, 1e-8 * scale) << "step " << n;
    EXPECT_LT(r.outsideCone, 1e-12 * scale) << "step " << n;
    EXPECT_LT(r.slipWhileInside, 1e-8) << "step " << n;
  }
  EXPECT_GT(problems, 300u);
  EXPECT_GE(largest, 12u) << "the pile should have many contacts at once";
  // The cubes end at rest on the floor or on each other, above the floor.
  for (int i = 0; i < 6; ++i)
    EXPECT_GT(frameOf(scene, "Cube" + std::to_string(i)).center.y(), 0.1 - 1e-6) << i;
}

struct BadContactInput {
  const char* what;
  std::string xml;
  const char* path;
  const char* field;
  const char* text;
};
void PrintTo(const BadContactInput& c, std::ostream* out) { *out << c.what; }

class ContactBadInput : public ::testing::TestWithParam<BadContactInput> {};

TEST_P(ContactBadInput, IsAnErrorNamingTheComponentAndField) {
  const BadContactInput& c = GetParam();
  Runtime runtime;
  Scene scene(runtime);
  bool failed = !scene.loadString(c.xml);
  for (int n = 0; n < 5 && !failed; ++n) failed = !scene.step();
  EXPECT_TRUE(failed) << c.what;
  EXPECT_TRUE(hasError(scene.log(), c.path, c.field, c.text))
      << c.what << ":\n" << describe(scene.log());
}

std::string response(const std::string& params) {
  return R"(<CollisionResponse name="response" response="FrictionContactConstraint" responseParams=")" +
         params + R"("/>)";
}

INSTANTIATE_TEST_SUITE_P(
    Lagrangian, ContactBadInput,
    ::testing::Values(
        BadContactInput{"a negative mu", root(kGeneric, response("mu=-0.2"), slope(0)),
                        "/root/response", "responseParams", "mu must be >= 0"},
        BadContactInput{"a mu that is not a number", root(kGeneric, response("mu=high"), slope(0)),
                        "/root/response", "responseParams", "'mu' must be a number"},
        BadContactInput{"a model's negative contactFriction",
                        root(kGeneric, response(""),
                             R"(<Node name="Box"><MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>
                                <OBBCollisionModel name="box" contactFriction="-1"/></Node>)"),
                        "/root/Box/box", "contactFriction", ""},
        BadContactInput{"a body in contact without a constraint correction",
                        root(kGeneric, response("mu=0.3"), slope(0) + cubeOn(0, "")),
                        "/root/freeMotionAnimationLoop", "constraintSolver",
                        "no constraint correction"}),
    NameFromWhat());

}  // namespace
}  // namespace stroma::test
