// SPDX-License-Identifier: MIT
// NewmarkImplicitSolver: the average-acceleration scheme keeps the energy of an undamped
// linear oscillator at any step size, its error falls 4 times when the step halves, Rayleigh
// damping dissipates, and a constant acceleration is integrated exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

const std::string kNewmark = R"(<NewmarkImplicitSolver/><SparseLDLSolver/>)";

double oscillatorEnergy(SolverScene& s, double k, double m) {
  return 0.5 * m * s.velocity(0).squaredNorm() + 0.5 * k * s.position(0).squaredNorm();
}

TEST(NewmarkImplicitSolver, KeepsTheEnergyOfAnUndampedOscillatorAtAnyStep) {
  const double k = 100, m = 1;          // omega = 10
  for (const double h : {0.01, 0.5}) {  // omega h = 0.1 and 5 (far past explicit limits)
    SCOPED_TRACE("h = " + std::to_string(h));
    SolverScene s(oscillatorScene(kNewmark, k, m, "1 0.3 0", "0 0 2", h));
    ASSERT_TRUE(s.loaded()) << s.log();
    const double e0 = oscillatorEnergy(s, k, m);
    double worst = 0;
    for (int n = 0; n < 10000; ++n) {
      ASSERT_TRUE(s.step()) << s.log();
      worst = std::max(worst, std::abs(oscillatorEnergy(s, k, m) / e0 - 1));
    }
    EXPECT_LT(worst, 1e-10);
  }
}

TEST(NewmarkImplicitSolver, ErrorQuartersWhenTheStepHalves) {
  const double omega = 2 * M_PI;
  auto errorAt = [&](double h) {
    SolverScene s(oscillatorScene(kNewmark, omega * omega, 1.0, "1 0 0", "0 0 0", h));
    EXPECT_TRUE(s.loaded()) << s.log();
    const int steps = static_cast<int>(std::lround(1.0 / h));
    for (int n = 0; n < steps; ++n) EXPECT_TRUE(s.step());
    const double t = steps * h;
    const double dx = s.position(0).x() - std::cos(omega * t);
    const double dv = s.velocity(0).x() + omega * std::sin(omega * t);
    return std::sqrt(dx * dx + dv * dv / (omega * omega));
  };
  const double e1 = errorAt(0.01), e2 = errorAt(0.005), e3 = errorAt(0.0025);
  EXPECT_NEAR(e1 / e2, 4.0, 0.05);
  EXPECT_NEAR(e2 / e3, 4.0, 0.05);
}

TEST(NewmarkImplicitSolver, RayleighDampingDissipatesEveryStep) {
  const double k = 100, m = 1;
  SolverScene s(oscillatorScene(
      R"(<NewmarkImplicitSolver rayleighMass="0.5" rayleighStiffness="0.01"/><SparseLDLSolver/>)",
      k, m, "1 0 0", "0 0 0", 0.01));
  ASSERT_TRUE(s.loaded()) << s.log();
  double previous = oscillatorEnergy(s, k, m);
  for (int n = 0; n < 500; ++n) {
    ASSERT_TRUE(s.step()) << s.log();
    const double e = oscillatorEnergy(s, k, m);
    EXPECT_LT(e, previous) << "step " << n + 1;
    previous = e;
  }
  // A damped oscillator of damping ratio zeta = (rm / omega + rs omega) / 2 = 0.075 loses
  // about exp(-2 zeta omega t) of its energy: exp(-7.5) at t = 5 s.
  EXPECT_NEAR(std::log(previous / (0.5 * k)), -7.5, 0.3);
}

TEST(NewmarkImplicitSolver, IntegratesFreeFallExactly) {
  const std::string xml = R"(<Node name="root" dt="0.1" gravity="0 -10 0">
  <Node name="Body">
    <NewmarkImplicitSolver/>
    <CGLinearSolver iterations="50" tolerance="1e-14" threshold="1e-30"/>
    <MechanicalObject name="dofs" position="0 0 0" velocity="1 0 0"/>
    <UniformMass vertexMass="3"/>
  </Node>
</Node>)";
  SolverScene s(xml);
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 10; ++n) ASSERT_TRUE(s.step()) << s.log();
  EXPECT_NEAR(s.position(0).x(), 1.0, 1e-12);
  EXPECT_NEAR(s.position(0).y(), -5.0, 1e-12);
  EXPECT_NEAR(s.velocity(0).y(), -10.0, 1e-12);
}

TEST(NewmarkImplicitSolver, StartsFromTheAccelerationOfANonDiagonalMass) {
  // A bar of consistent mass m/3 [[2, 1], [1, 2]] (m = 2) pushed at point 0 by F = 3 N:
  // a = M^-1 F = (2F/m, -F/m) from the start, integrated exactly: x = a t^2 / 2.
  const std::string xml = R"(<Node name="root" dt="0.1" gravity="0 0 0">
  <Node name="Body">
    <NewmarkImplicitSolver/>
    <CGLinearSolver iterations="50" tolerance="1e-15" threshold="1e-30"/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <TestBarMass pointMass="2"/>
    <ConstantForceField indices="0" force="0 3 0"/>
  </Node>
</Node>)";
  SolverScene s(xml);
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 10; ++n) ASSERT_TRUE(s.step()) << s.log();
  EXPECT_NEAR(s.position(0).y(), 0.5 * 3.0, 1e-12);
  EXPECT_NEAR(s.position(1).y(), -0.5 * 1.5, 1e-12);
  EXPECT_NEAR(s.velocity(0).y(), 3.0, 1e-12);
}

}  // namespace
}  // namespace stroma::test
