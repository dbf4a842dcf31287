// SPDX-License-Identifier: MIT
// CentralDifferenceSolver: the position recurrence of seed 000 eq. 3.3 with Rayleigh mass
// damping, bounded energy below the Courant step, divergence (stopped with a message) above.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

constexpr double kStiffness = 100, kMass = 2;  // omega = sqrt(50) = 7.07 rad/s

TEST(CentralDifferenceSolver, PositionsFollowTheCentralDifferenceRecurrence) {
  // (m/h^2 - g/2h) P_{n+1} = F_n + 2m/h^2 P_n - (m/h^2 + g/2h) P_{n-1}, g = -rm m, F = -k P.
  const double h = 0.01, rm = 3.0;
  SolverScene s(oscillatorScene(R"(<CentralDifferenceSolver rayleighMass="3"/>)", kStiffness, kMass,
                                "1 0.5 0", "0 0 0", h));
  ASSERT_TRUE(s.loaded()) << s.log();
  const double g = -rm * kMass;
  std::vector<Vec3d> P{s.position(0)};
  for (int n = 0; n < 200; ++n) {
    ASSERT_TRUE(s.step()) << s.log();
    P.push_back(s.position(0));
  }
  // P_{-1} = P_0 - h v_{-1/2} = P_0 (starting at rest) closes the first step.
  for (std::size_t n = 0; n + 1 < P.size(); ++n) {
    const Vec3d previous = n == 0 ? P[0] : P[n - 1];
    const Vec3d rhs = -kStiffness * P[n] + 2 * kMass / (h * h) * P[n] -
                      (kMass / (h * h) + g / (2 * h)) * previous;
    const Vec3d lhs = (kMass / (h * h) - g / (2 * h)) * P[n + 1];
    EXPECT_LT((lhs - rhs).norm(), 1e-9 * rhs.norm()) << "step " << n + 1;
  }
}

TEST(CentralDifferenceSolver, KeepsTheEnergyBoundedBelowTheCourantStep) {
  const double omega = std::sqrt(kStiffness / kMass);
  const double h = 1.9 / omega;  // just below the limit omega h < 2
  SolverScene s(
      oscillatorScene(R"(<CentralDifferenceSolver/>)", kStiffness, kMass, "1 0 0", "0 0 0", h));
  ASSERT_TRUE(s.loaded()) << s.log();
  // With the half-step velocity, Q = w^2 x_{n+1}^2 + v^2 - h w^2 x_{n+1} v is invariant, and
  // Q bounds the energy for w h < 2 (it is then a positive definite form).
  auto shadow = [&] {
    const double x = s.position(0).x(), v = s.velocity(0).x();
    return omega * omega * x * x + v * v - h * omega * omega * x * v;
  };
  const double q0 = shadow();
  double largest = 0;
  for (int n = 0; n < 100000; ++n) {
    ASSERT_TRUE(s.step()) << s.log();
    largest = std::max(largest, std::abs(s.position(0).x()));
  }
  EXPECT_NEAR(shadow() / q0, 1.0, 1e-9);
  // Amplitude bound from Q: x^2 <= Q / (w^2 (1 - (w h / 2)^2)).
  EXPECT_LE(largest * largest, q0 / (omega * omega * (1 - 0.25 * 1.9 * 1.9)) * (1 + 1e-9));
  EXPECT_GE(largest, 1.0);
}

TEST(CentralDifferenceSolver, AboveTheCourantStepTheRunStopsAtTheFirstNonFiniteValue) {
  const double omega = std::sqrt(kStiffness / kMass);
  SolverScene s(oscillatorScene(R"(<CentralDifferenceSolver/>)", kStiffness, kMass, "1 0 0",
                                "0 0 0", 2.1 / omega));
  ASSERT_TRUE(s.loaded()) << s.log();
  int failedStep = 0;
  for (int n = 1; n <= 10000 && !failedStep; ++n)
    if (!s.step()) failedStep = n;
  ASSERT_GT(failedStep, 100) << "the amplitude grows by about 1.9 per step before overflowing";
  const Message m = findError(s.scene().log(), "diverged");
  EXPECT_NE(m.text.find("after step " + std::to_string(failedStep) + " of /root/Body/dofs"),
            std::string::npos)
      << m.text;
  EXPECT_EQ(m.componentClass, "CentralDifferenceSolver");
}

}  // namespace
}  // namespace stroma::test
