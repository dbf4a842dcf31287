// SPDX-License-Identifier: MIT
// EulerExplicitSolver on a harmonic oscillator (m = 1 kg, k = 100 N/m, omega = 10 rad/s):
// the symplectic scheme keeps a modified energy exactly and the energy bounded; forward Euler
// multiplies the energy by 1 + (omega h)^2 per step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

constexpr double kStiffness = 100, kMass = 1, kOmega = 10;

TEST(EulerExplicitSolver, SymplecticKeepsTheEnergyBoundedOver1e5Steps) {
  const double h = 0.01;  // omega h = 0.1, below the stability limit 2
  SolverScene s(oscillatorScene(R"(<EulerExplicitSolver symplectic="true"/>)", kStiffness, kMass,
                                "1 0 0", "0 0 0", h));
  ASSERT_TRUE(s.loaded()) << s.log();
  auto energy = [&] {
    const double x = s.position(0).x(), v = s.velocity(0).x();
    return 0.5 * kMass * v * v + 0.5 * kStiffness * x * x;
  };
  // The map (x, v) -> (x + h v', v' = v - h w^2 x) has determinant 1 and keeps exactly
  // Q = w^2 x^2 + v^2 - h w^2 x v (a shadow energy); the energy oscillates about it.
  auto shadow = [&] {
    const double x = s.position(0).x(), v = s.velocity(0).x();
    return kOmega * kOmega * x * x + v * v - h * kOmega * kOmega * x * v;
  };
  const double e0 = energy(), q0 = shadow();
  double worst = 0, worstShadow = 0, firstMax = 0, lastMax = 0;
  constexpr int kSteps = 100000;
  for (int n = 1; n <= kSteps; ++n) {
    ASSERT_TRUE(s.step()) << s.log();
    const double deviation = std::abs(energy() / e0 - 1);
    worst = std::max(worst, deviation);
    worstShadow = std::max(worstShadow, std::abs(shadow() / q0 - 1));
    if (n <= 1000) firstMax = std::max(firstMax, deviation);
    if (n > kSteps - 1000) lastMax = std::max(lastMax, deviation);
  }
  EXPECT_LT(worstShadow, 1e-10);
  EXPECT_LT(worst, kOmega * h);          // bounded: O(omega h), about 0.05 here
  EXPECT_NEAR(lastMax, firstMax, 1e-6);  // and without drift
  EXPECT_GT(worst, 0.01);                // (it does oscillate: not a trivial run)
}

TEST(EulerExplicitSolver, ForwardEulerGainsEnergyByOnePlusOmegaHSquaredPerStep) {
  const double h = 0.01;
  SolverScene s(oscillatorScene(R"(<EulerExplicitSolver symplectic="false"/>)", kStiffness, kMass,
                                "1 0 0", "0 0 0", h));
  ASSERT_TRUE(s.loaded()) << s.log();
  const double e0 = s.energy();
  constexpr int kSteps = 500;
  for (int n = 0; n < kSteps; ++n) ASSERT_TRUE(s.step()) << s.log();
  // (w x + i v) is multiplied by (1 - i w h) each step.
  const double expected = std::pow(1 + kOmega * kOmega * h * h, kSteps);
  EXPECT_NEAR(s.energy() / e0, expected, 1e-10 * expected);
}

TEST(EulerExplicitSolver, FallsUnderGravityAsTheSemiImplicitSchemeSays) {
  // v_n = n h g, x_n = h^2 g n (n + 1) / 2 with symplectic Euler.
  const std::string xml = R"(<Node name="root" dt="0.1" gravity="0 -10 0">
  <Node name="Body">
    <EulerExplicitSolver/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass vertexMass="2"/>
  </Node>
</Node>)";
  SolverScene s(xml);
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 10; ++n) ASSERT_TRUE(s.step()) << s.log();
  EXPECT_NEAR(s.velocity(0).y(), -10.0, 1e-12);
  EXPECT_NEAR(s.position(0).y(), -0.01 * 10 * 10 * 11 / 2, 1e-12);
}

// Two points of a bar with the consistent mass m/3 [[2, 1], [1, 2]]: a force F on point 0
// accelerates it by 2F/m and point 1 by -F/m (M^-1 = 1/m [[2, -1], [-1, 2]]).
std::string barScene(const std::string& solvers) {
  return R"(<Node name="root" dt="0.1" gravity="0 0 0">
  <Node name="Body">
    )" + solvers +
         R"(
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <TestBarMass pointMass="2"/>
    <ConstantForceField indices="0" force="0 3 0"/>
  </Node>
</Node>)";
}

TEST(EulerExplicitSolver, InvertsANonDiagonalMassWithTheLinearSolver) {
  SolverScene s(barScene("<EulerExplicitSolver/><SparseLDLSolver/>"));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_NEAR(s.velocity(0).y(), 0.1 * 2 * 3 / 2.0, 1e-14);
  EXPECT_NEAR(s.velocity(1).y(), -0.1 * 3 / 2.0, 1e-14);
  EXPECT_NEAR(s.position(0).y(), 0.1 * 0.1 * 2 * 3 / 2.0, 1e-14);
}

TEST(EulerExplicitSolver, SaysWhenANonDiagonalMassHasNoLinearSolver) {
  SolverScene s(barScene("<EulerExplicitSolver/>"));
  ASSERT_TRUE(s.loaded()) << s.log();
  EXPECT_FALSE(s.step());
  const Message m = findError(s.scene().log(), "lumped");
  EXPECT_NE(m.text.find("TestBarMass is not one"), std::string::npos) << s.log();
}

}  // namespace
}  // namespace stroma::test
