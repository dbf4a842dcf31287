// SPDX-License-Identifier: MIT
// StaticSolver: the equilibrium of a spring chain held at one end and pulled at the other,
// linear (exact after one Newton iteration) and hardening (Newton with the line search); a
// stall when the tangent is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

constexpr int kPoints = 6;

// Points 0..5 on the x axis, 1 m apart, point 0 fixed, springs (i, i+1), a force F along x on
// the last point; y and z held by weak lateral anchors that are at rest at equilibrium.
std::string chainScene(const std::string& solver, double k, double c, double force,
                       const std::string& linearSolver = "<SparseLDLSolver/>") {
  std::ostringstream positions, springs;
  for (int i = 0; i < kPoints; ++i) positions << i << " 0 0  ";
  for (int i = 0; i + 1 < kPoints; ++i) springs << i << " " << i + 1 << "  ";
  std::ostringstream xml;
  xml << R"(<Node name="root" dt="1" gravity="0 0 0">
  <Node name="Body">
    )" << solver
      << "\n    " << linearSolver << R"(
    <MechanicalObject name="dofs" position=")"
      << positions.str() << R"("/>
    <UniformMass vertexMass="1"/>
    <TestSpringForceField springs=")"
      << springs.str() << "\" stiffness=\"" << k << "\" cubicStiffness=\"" << c << R"("/>
    <TestAnchorForceField stiffness="0 1 1"/>
    <FixedProjectiveConstraint indices="0"/>
    <ConstantForceField indices=")"
      << kPoints - 1 << "\" force=\"" << force << R"( 0 0"/>
  </Node>
</Node>)";
  return xml.str();
}

// The elongation of each spring of the chain: k e + c e^3 = F (every spring carries F).
double elongation(double k, double c, double F) {
  double e = F / k < 1 ? F / k : std::cbrt(F / c);
  for (int i = 0; i < 100; ++i) e -= (k * e + c * e * e * e - F) / (k + 3 * c * e * e);
  return e;
}

void expectChainAtEquilibrium(SolverScene& s, double e, double tolerance) {
  for (int i = 0; i < kPoints; ++i) {
    EXPECT_NEAR(s.position(i).x(), i * (1 + e), tolerance) << "point " << i;
    EXPECT_NEAR(s.position(i).y(), 0.0, tolerance);
    EXPECT_EQ(s.velocity(i), Vec3d::Zero());
  }
}

TEST(StaticSolver, LinearChainReachesTheExactEquilibriumInOneIteration) {
  SolverScene s(chainScene(R"(<StaticSolver name="solver"/>)", 10.0, 0.0, 2.0));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  expectChainAtEquilibrium(s, 0.2, 1e-12);  // e = F / k
  EXPECT_EQ(s.field("solver", "lastIterations"), "1");
  EXPECT_EQ(s.field("solver", "lastConverged"), "1");
  EXPECT_LT(std::stod(s.field("solver", "lastResidual")), 1e-10);
  // At equilibrium a further step changes nothing (converged before any iteration).
  ASSERT_TRUE(s.step()) << s.log();
  expectChainAtEquilibrium(s, 0.2, 1e-12);
  EXPECT_EQ(s.field("solver", "lastIterations"), "0");
}

TEST(StaticSolver, ImposedMotionOfTheStepIsInTheEquilibriumOfThatStep) {
  // The last point moved by 1 m over [0, 1] s (LinearMovementProjectiveConstraint), no force:
  // the equilibrium at the end of the step has every spring stretched by 1/5. The imposed
  // positions of the end of the step must be in place before Newton, not set after it.
  std::string xml = chainScene(R"(<StaticSolver name="solver"/>)", 10.0, 0.0, 0.0);
  xml.insert(xml.rfind("  </Node>"),
             "    <LinearMovementProjectiveConstraint indices=\"5\" keyTimes=\"0 1\" "
             "movements=\"0 0 0  1 0 0\"/>\n");
  SolverScene s(xml);
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  expectChainAtEquilibrium(s, 0.2, 1e-12);
}

const std::string kNewton = R"(<StaticSolver name="solver" newton_iterations="30"
    absolute_residual_tolerance_threshold="1e-9" relative_residual_tolerance_threshold="-1"
    absolute_correction_tolerance_threshold="-1" relative_correction_tolerance_threshold="-1")";

TEST(StaticSolver, HardeningChainConvergesWithTheLineSearch) {
  // k e + c e^3 = F with k = 1, c = 1000, F = 1000: a first Newton step from rest (tangent
  // k = 1) would stretch each spring by 1000 m; the line search cuts it back.
  const double k = 1, c = 1000, F = 1000;
  SolverScene s(chainScene(kNewton + R"( maxNbIterationsLineSearch="20"/>)", k, c, F));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  expectChainAtEquilibrium(s, elongation(k, c, F), 1e-10);
  EXPECT_EQ(s.field("solver", "lastConverged"), "1");
  EXPECT_LE(std::stoi(s.field("solver", "lastIterations")), 10);
  EXPECT_EQ(s.scene().log().count(MessageLevel::warning), 0u) << s.log();
}

TEST(StaticSolver, WithoutLineSearchTheSameChainNeedsManyMoreIterations) {
  const double k = 1, c = 1000, F = 1000;
  SolverScene s(
      chainScene(R"(<StaticSolver name="solver" newton_iterations="10" maxNbIterationsLineSearch="1"
          absolute_residual_tolerance_threshold="1e-9" relative_residual_tolerance_threshold="-1"
          absolute_correction_tolerance_threshold="-1" relative_correction_tolerance_threshold="-1"/>)",
                 k, c, F));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("solver", "lastConverged"), "0");
  // Full Newton steps from the 1000-fold overshoot shrink by about 2/3 each.
  EXPECT_GT(s.position(kPoints - 1).x(), 2 * kPoints);
  const auto warnings = s.scene().log().messages();
  bool warned = false;
  for (const Message& m : warnings)
    warned |=
        m.level == MessageLevel::warning &&
        m.text.find("Newton did not converge in 10 iterations at step 1") != std::string::npos &&
        m.field == "newton_iterations";
  EXPECT_TRUE(warned) << s.log();
}

TEST(StaticSolver, NegativeThresholdsDisableEveryCriterion) {
  // Linear chain, 3 iterations, nothing can stop them early: 3 iterations done.
  SolverScene s(chainScene(R"(<StaticSolver name="solver" newton_iterations="3"
      absolute_residual_tolerance_threshold="-1" relative_residual_tolerance_threshold="-1"
      absolute_correction_tolerance_threshold="-1" relative_correction_tolerance_threshold="-1"/>)",
                           10.0, 0.0, 2.0));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("solver", "lastIterations"), "3");
  expectChainAtEquilibrium(s, 0.2, 1e-12);
}

TEST(StaticSolver, TakesItsParametersFromALinkedNewtonRaphsonSolver) {
  // SOFA's newer form: the same hardening chain, parameters on a NewtonRaphsonSolver.
  const double k = 1, c = 1000, F = 1000;
  SolverScene s(chainScene(R"(<NewtonRaphsonSolver name="newton" maxNbIterationsNewton="30"
        maxNbIterationsLineSearch="20" absoluteResidualStoppingThreshold="1e-9"
        relativeInitialStoppingThreshold="0" relativeSuccessiveStoppingThreshold="0"/>
    <StaticSolver name="solver" newtonSolver="@newton"/>)",
                           k, c, F));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  expectChainAtEquilibrium(s, elongation(k, c, F), 1e-10);
  EXPECT_EQ(s.field("newton", "status"), "ConvergedAbsoluteResidual");
  EXPECT_LE(std::stoi(s.field("solver", "lastIterations")), 10);

  // With 5 step lengths (down to 1/16) the line search cannot cut the first overshoot back:
  // the full step is taken (updateStateWhenDiverged) and the status says so.
  SolverScene few(chainScene(R"(<NewtonRaphsonSolver name="newton" maxNbIterationsNewton="1"
        warnWhenLineSearchFails="false" warnWhenDiverge="false" absoluteResidualStoppingThreshold="1e-9"
        relativeInitialStoppingThreshold="0" relativeSuccessiveStoppingThreshold="0"/>
    <StaticSolver name="solver" newtonSolver="@newton"/>)",
                             k, c, F));
  ASSERT_TRUE(few.loaded()) << few.log();
  ASSERT_TRUE(few.step()) << few.log();
  EXPECT_EQ(few.field("newton", "status"), "DivergedLineSearch");
  EXPECT_NEAR(few.position(1).x(), 1 + F / k, 1e-9);  // the full first Newton step
  EXPECT_EQ(few.scene().log().count(MessageLevel::warning), 0u) << few.log();
}

TEST(StaticSolver, AWrongTangentStallsWithAWarningAndKeepsThePosition) {
  // The tangent has the wrong sign: the Newton direction increases the residual for every
  // step length, the line search finds nothing, the solver says so and stays put.
  const std::string xml = R"(<Node name="root" dt="1" gravity="0 0 0">
  <Node name="Body">
    <StaticSolver name="solver" newton_iterations="5"/>
    <CGLinearSolver iterations="10" tolerance="1e-12" threshold="1e-30"/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <TestAnchorForceField stiffness="4 4 4" tangentScale="-1"/>
    <ConstantForceField force="1 0 0"/>
  </Node>
</Node>)";
  SolverScene s(xml);
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.position(0), Vec3d::Zero());
  EXPECT_EQ(s.field("solver", "lastConverged"), "0");
  bool warned = false;
  for (const Message& m : s.scene().log().messages())
    warned |=
        m.level == MessageLevel::warning &&
        m.text.find("the line search failed at step 1, Newton iteration 1") != std::string::npos;
  EXPECT_TRUE(warned) << s.log();
}

}  // namespace
}  // namespace stroma::test
