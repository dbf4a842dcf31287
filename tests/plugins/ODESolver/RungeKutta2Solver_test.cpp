// SPDX-License-Identifier: MIT
// RungeKutta2Solver: second-order convergence on a harmonic oscillator (the error falls 4 times
// when the step halves), the amplification sqrt(1 + (omega h)^4 / 4) of one step, and a
// constant acceleration integrated exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

const std::string kSolver = "<RungeKutta2Solver/>";

// Error at t = 1 s of an oscillator of period 1 s started at x = 1, in the energy norm.
double oscillatorError(double h) {
  const double omega = 2 * M_PI;
  SolverScene s(oscillatorScene(kSolver, omega * omega, 1.0, "1 0 0", "0 0 0", h));
  EXPECT_TRUE(s.loaded()) << s.log();
  const int steps = static_cast<int>(std::lround(1.0 / h));
  for (int n = 0; n < steps; ++n) EXPECT_TRUE(s.step()) << s.log();
  const double t = steps * h;
  const double dx = s.position(0).x() - std::cos(omega * t);
  const double dv = s.velocity(0).x() + omega * std::sin(omega * t);
  return std::sqrt(dx * dx + dv * dv / (omega * omega));
}

TEST(RungeKutta2Solver, ConvergesAtOrderTwoOnAHarmonicOscillator) {
  const double e1 = oscillatorError(0.004), e2 = oscillatorError(0.002),
               e3 = oscillatorError(0.001);
  EXPECT_LT(e1, 1e-2);
  EXPECT_NEAR(e1 / e2, 4.0, 0.1);
  EXPECT_NEAR(e2 / e3, 4.0, 0.1);
}

TEST(RungeKutta2Solver, AmplifiesAnUndampedOscillationBySqrt1PlusOmegaH4Over4) {
  const double k = 100, h = 0.05, omega = 10, w = omega * h;  // omega h = 0.5
  SolverScene s(oscillatorScene(kSolver, k, 1.0, "1 0 0", "0 0 0", h));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  // One step from (1, 0): x = 1 - w^2 / 2, v / omega = -w.
  EXPECT_NEAR(s.position(0).x(), 1 - w * w / 2, 1e-14);
  EXPECT_NEAR(s.velocity(0).x() / omega, -w, 1e-14);
  const double amplitude = std::hypot(s.position(0).x(), s.velocity(0).x() / omega);
  EXPECT_NEAR(amplitude, std::sqrt(1 + w * w * w * w / 4), 1e-14);
}

TEST(RungeKutta2Solver, IntegratesAConstantAccelerationExactly) {
  SolverScene s(R"(<Node name="root" dt="0.1" gravity="0 0 0">
  <Node name="Body">
    <RungeKutta2Solver/>
    <MechanicalObject name="dofs" position="0 0 0" velocity="1 2 0"/>
    <UniformMass vertexMass="2"/>
    <ConstantForceField force="0 -3 0"/>
  </Node>
</Node>)");
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 10; ++n) ASSERT_TRUE(s.step()) << s.log();
  // x = x0 + v0 t + a t^2 / 2 at t = 1 s, a = -1.5 m/s^2.
  EXPECT_NEAR(s.position(0).x(), 1.0, 1e-12);
  EXPECT_NEAR(s.position(0).y(), 2.0 - 0.75, 1e-12);
  EXPECT_NEAR(s.velocity(0).y(), 2.0 - 1.5, 1e-12);
}

}  // namespace
}  // namespace stroma::test
