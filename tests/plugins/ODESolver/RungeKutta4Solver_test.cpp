// SPDX-License-Identifier: MIT
// RungeKutta4Solver: fourth-order convergence on a harmonic oscillator (the error falls 16
// times when the step halves), exact integration of a constant acceleration, constraints.
#include <gtest/gtest.h>

#include <cmath>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

// Error at t = 1 s of an oscillator of period 1 s started at x = 1, in the energy norm.
double oscillatorError(const std::string& solvers, double h) {
  const double omega = 2 * M_PI;
  SolverScene s(oscillatorScene(solvers, omega * omega, 1.0, "1 0 0", "0 0 0", h));
  EXPECT_TRUE(s.loaded()) << s.log();
  const int steps = static_cast<int>(std::lround(1.0 / h));
  for (int n = 0; n < steps; ++n) EXPECT_TRUE(s.step()) << s.log();
  const double t = steps * h;
  const double dx = s.position(0).x() - std::cos(omega * t);
  const double dv = s.velocity(0).x() + omega * std::sin(omega * t);
  return std::sqrt(dx * dx + dv * dv / (omega * omega));
}

TEST(RungeKutta4Solver, ConvergesAtOrderFourOnAHarmonicOscillator) {
  const std::string solver = "<RungeKutta4Solver/>";
  const double e1 = oscillatorError(solver, 0.02), e2 = oscillatorError(solver, 0.01),
               e3 = oscillatorError(solver, 0.005);
  EXPECT_LT(e1, 1e-4);
  EXPECT_NEAR(e1 / e2, 16.0, 0.5);
  EXPECT_NEAR(e2 / e3, 16.0, 0.5);
}

TEST(RungeKutta4Solver, IntegratesAConstantAccelerationExactlyAndKeepsFixedPointsFixed) {
  const std::string xml = R"(<Node name="root" dt="0.1" gravity="0 0 0">
  <Node name="Body">
    <RungeKutta4Solver/>
    <MechanicalObject name="dofs" position="0 0 0  5 0 0" velocity="1 2 0  0 0 0"/>
    <UniformMass vertexMass="2"/>
    <ConstantForceField force="0 -3 0"/>
    <FixedProjectiveConstraint indices="1"/>
  </Node>
</Node>)";
  SolverScene s(xml);
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 10; ++n) ASSERT_TRUE(s.step()) << s.log();
  // x = x0 + v0 t + a t^2 / 2 at t = 1 s, a = -1.5 m/s^2.
  EXPECT_NEAR(s.position(0).x(), 1.0, 1e-12);
  EXPECT_NEAR(s.position(0).y(), 2.0 - 0.75, 1e-12);
  EXPECT_NEAR(s.velocity(0).y(), 2.0 - 1.5, 1e-12);
  EXPECT_EQ(s.position(1), Vec3d(5, 0, 0));
  EXPECT_EQ(s.velocity(1), Vec3d(0, 0, 0));
}

}  // namespace
}  // namespace stroma::test
