// SPDX-License-Identifier: MIT
// EulerImplicitSolver: unconditional stability and the amplitude decay of backward Euler on a
// harmonic oscillator (|1 / (1 + i omega h)| per step, REFERENCES.md Dynamics), first-order
// convergence, and the Newton iterations of newtonIterations > 1 on a hardening spring.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

const std::string kSolvers = R"(<EulerImplicitSolver/><SparseLDLSolver/>)";

// sqrt(x^2 + (v / omega)^2): the amplitude of the oscillator.
double amplitude(SolverScene& s, double omega) {
  const Vec3d x = s.position(0), v = s.velocity(0);
  return std::sqrt(x.squaredNorm() + v.squaredNorm() / (omega * omega));
}

// Round-off grows as epsilon (omega h)^2 (v1 = (x1 - x0) / h cancels): `tolerance` relative.
void expectDecayPerStep(double stiffness, double h, int steps, double tolerance = 1e-9) {
  const double omega = std::sqrt(stiffness);  // m = 1 kg
  SolverScene s(oscillatorScene(kSolvers, stiffness, 1.0, "1 0 0", "0 0 0", h));
  ASSERT_TRUE(s.loaded()) << s.log();
  const double expected = 1 / std::sqrt(1 + omega * h * omega * h);
  double previous = amplitude(s, omega);
  for (int n = 1; n <= steps; ++n) {
    ASSERT_TRUE(s.step()) << s.log();
    const double a = amplitude(s, omega);
    ASSERT_TRUE(std::isfinite(a));
    EXPECT_NEAR(a / previous, expected, tolerance * expected) << "step " << n;
    previous = a;
  }
}

TEST(EulerImplicitSolver, IsStableOnAStiffSystemAndDampsAsBackwardEulerShould) {
  // k = 1e9 N/m on 1 kg (a 1 m^2, 1 m bar of E = 1e9 Pa): omega h = 3162 at h = 0.1 s,
  // 1500 times the explicit stability limit.
  expectDecayPerStep(1e9, 0.1, 6, 1e-7);
}

TEST(EulerImplicitSolver, DampsTheAmplitudeBy1OverSqrt1PlusOmegaHSquaredPerStep) {
  expectDecayPerStep(100.0, 0.1, 100);   // omega h = 1: a factor 0.7071 per step
  expectDecayPerStep(100.0, 0.01, 100);  // omega h = 0.1
}

TEST(EulerImplicitSolver, ErrorHalvesWhenTheStepHalves) {
  const double omega = 2 * M_PI;  // k = 4 pi^2, m = 1: period 1 s
  auto errorAt = [&](double h) {
    SolverScene s(oscillatorScene(kSolvers, omega * omega, 1.0, "1 0 0", "0 0 0", h));
    EXPECT_TRUE(s.loaded()) << s.log();
    const int steps = static_cast<int>(std::lround(0.5 / h));
    for (int n = 0; n < steps; ++n) EXPECT_TRUE(s.step());
    return std::abs(s.position(0).x() - std::cos(omega * 0.5));
  };
  const double e1 = errorAt(0.002), e2 = errorAt(0.001);
  EXPECT_NEAR(e1 / e2, 2.0, 0.05);
}

// One point on a hardening anchor f = -(k + c x^2) x, from x0 = 1 at rest. Backward Euler's
// equation: v1 = v0 + h f(x0 + h v1) / m.
struct HardeningStep {
  static constexpr double k = 1, c = 1000, h = 0.05;
  static double force(double x) { return -(k + c * x * x) * x; }
  /// |m (v1 - v0) - h f(x1)| / |h f(x0)| after one step.
  static double residual(SolverScene& s) {
    const double x1 = s.position(0).x(), v1 = s.velocity(0).x();
    return std::abs(v1 - h * force(x1)) / std::abs(h * force(1.0));
  }
  static std::string scene(const std::string& solverAttributes) {
    return R"(<Node name="root" dt="0.05" gravity="0 0 0">
  <Node name="Body">
    <EulerImplicitSolver name="solver" )" +
           solverAttributes + R"(/>
    <SparseLDLSolver/>
    <MechanicalObject name="dofs" position="1 0 0" rest_position="0 0 0"/>
    <UniformMass vertexMass="1"/>
    <TestAnchorForceField stiffness="1 1 1" cubicStiffness="1000"/>
  </Node>
</Node>)";
  }
};

TEST(EulerImplicitSolver, NewtonIterationsSolveTheNonlinearImplicitEquation) {
  SolverScene linearized(HardeningStep::scene(R"(computeResidual="true")"));
  ASSERT_TRUE(linearized.loaded()) << linearized.log();
  ASSERT_TRUE(linearized.step()) << linearized.log();
  const double linearizedResidual = HardeningStep::residual(linearized);
  EXPECT_GT(linearizedResidual, 1e-2);  // one linearization is far from the implicit state
  EXPECT_EQ(linearized.field("solver", "lastIterations"), "1");
  // computeResidual reports the same residual, normalized by the first right-hand side.
  EXPECT_NEAR(std::stod(linearized.field("solver", "lastResidual")), linearizedResidual, 1e-9);

  SolverScene newton(HardeningStep::scene(R"(newtonIterations="20" newtonTolerance="1e-13")"));
  ASSERT_TRUE(newton.loaded()) << newton.log();
  ASSERT_TRUE(newton.step()) << newton.log();
  EXPECT_LT(HardeningStep::residual(newton), 1e-12);
  EXPECT_LE(std::stoi(newton.field("solver", "lastIterations")), 10);
  EXPECT_LT(std::stod(newton.field("solver", "lastResidual")), 1e-13);
  EXPECT_EQ(newton.scene().log().count(MessageLevel::warning), 0u) << newton.log();
}

TEST(EulerImplicitSolver, NewtonThatDoesNotConvergeWarnsOnce) {
  SolverScene s(HardeningStep::scene(R"(newtonIterations="2" newtonTolerance="1e-15")"));
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 3; ++n) ASSERT_TRUE(s.step()) << s.log();
  std::size_t warnings = 0;
  for (const Message& m : s.scene().log().messages())
    if (m.level == MessageLevel::warning) {
      ++warnings;
      EXPECT_NE(m.text.find("Newton did not converge in 2 iterations at step 1"), std::string::npos)
          << m.text;
      EXPECT_EQ(m.field, "newtonIterations");
    }
  EXPECT_EQ(warnings, 1u) << s.log();
}

TEST(EulerImplicitSolver, NewtonOnALinearSystemStopsAfterTheFirstSolve) {
  // Linear forces: the linearized step is already the implicit solution, so the residual
  // checked after it ends the iterations.
  SolverScene s(oscillatorScene(
      R"(<EulerImplicitSolver name="solver" newtonIterations="5" newtonTolerance="1e-10"/>
         <SparseLDLSolver/>)",
      100.0, 1.0));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("solver", "lastIterations"), "1");
  EXPECT_LT(std::stod(s.field("solver", "lastResidual")), 1e-12);
}

}  // namespace
}  // namespace stroma::test
