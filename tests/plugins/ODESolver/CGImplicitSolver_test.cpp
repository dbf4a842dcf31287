// SPDX-License-Identifier: MIT
// CGImplicitSolver (SOFA's CGImplicit): backward Euler's amplitude decay on a harmonic
// oscillator, SOFA's default damping, the same states as an EulerImplicitSolver with a CGLinearSolver of the same
// settings, and its CG settings reaching the CG it owns.
#include <gtest/gtest.h>

#include <cmath>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

TEST(CGImplicitSolver, DampsTheAmplitudeBy1OverSqrt1PlusOmegaHSquaredPerStep) {
  const double k = 100, h = 0.1, omega = 10;  // m = 1 kg: omega h = 1
  SolverScene s(oscillatorScene(R"(<CGImplicit iterations="10" tolerance="1e-12" threshold="1e-30" rayleighMass="0" rayleighStiffness="0"/>)", k, 1.0,
                                "1 0 0", "0 0 0", h));
  ASSERT_TRUE(s.loaded()) << s.log();
  auto amplitude = [&] {
    const Vec3d x = s.position(0), v = s.velocity(0);
    return std::sqrt(x.squaredNorm() + v.squaredNorm() / (omega * omega));
  };
  double previous = amplitude();
  for (int n = 1; n <= 50; ++n) {
    ASSERT_TRUE(s.step()) << s.log();
    EXPECT_NEAR(amplitude() / previous, 1 / std::sqrt(2.0), 1e-9) << "step " << n;
    previous = amplitude();
  }
}

// SOFA reads CGImplicit with the old defaults rayleighMass = rayleighStiffness = 0.1 (measured on
// runSofa: a free-falling cloth point moves by h^2 g / (1 + 0.1 h) in its first step).
TEST(CGImplicitSolver, DampsWithSofasDefaultRayleighMassOf0_1) {
  const double h = 0.05, g = 9;
  SolverScene s(R"(<Node name="root" dt="0.05" gravity="0 -9 0">
  <Node name="Body">
    <CGImplicit/>
    <MechanicalObject position="0 0 0"/>
    <UniformMass vertexMass="3"/>
  </Node>
</Node>)");
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_NEAR(s.velocity(0).y(), -h * g / (1 + 0.1 * h), 1e-14);
  EXPECT_NEAR(s.position(0).y(), -h * h * g / (1 + 0.1 * h), 1e-14);
}

// Three points on anchors of three different stiffnesses per axis: CG needs three iterations
// for the exact solve, so a cap of 2 shows in the states.
std::string threeAxes(const std::string& solvers) {
  return R"(<Node name="root" dt="0.05" gravity="0 0 0">
  <Node name="Body">)" + solvers + R"(
    <MechanicalObject name="dofs" position="1 1 1  0.5 -1 2  0 0 1" rest_position="0 0 0 0 0 0 0 0 0"
                      velocity="0 1 0  1 0 0  0 0 -1"/>
    <UniformMass vertexMass="2"/>
    <TestAnchorForceField stiffness="10 200 3000"/>
  </Node>
</Node>)";
}

double largestDifference(SolverScene& a, SolverScene& b) {
  double d = 0;
  for (std::size_t i = 0; i < 3; ++i)
    d = std::max({d, (a.position(i) - b.position(i)).norm(), (a.velocity(i) - b.velocity(i)).norm()});
  return d;
}

TEST(CGImplicitSolver, StepsAsEulerImplicitSolverWithACGLinearSolver) {
  for (const char* iterations : {"25", "2"}) {
    const std::string settings = std::string(" iterations=\"") + iterations +
                                 "\" tolerance=\"1e-9\" threshold=\"1e-20\"";
    SolverScene one(threeAxes("<CGImplicit rayleighMass=\"0.3\" rayleighStiffness=\"0.02\"" +
                              settings + "/>"));
    SolverScene two(threeAxes(
        "<EulerImplicitSolver rayleighMass=\"0.3\" rayleighStiffness=\"0.02\"/><CGLinearSolver" +
        settings + "/>"));
    ASSERT_TRUE(one.loaded()) << one.log();
    ASSERT_TRUE(two.loaded()) << two.log();
    for (int n = 0; n < 40; ++n) {
      one.step();
      two.step();
    }
    EXPECT_LT(largestDifference(one, two), 1e-14) << "iterations " << iterations;
  }
}

TEST(CGImplicitSolver, ItsIterationCapReachesItsCGAndItsWarningsAreItsOwn) {
  SolverScene capped(threeAxes(R"(<CGImplicit name="solver" iterations="2" tolerance="1e-12"/>)"));
  SolverScene exact(threeAxes(R"(<CGImplicit iterations="25" tolerance="1e-12"/>)"));
  ASSERT_TRUE(capped.loaded()) << capped.log();
  ASSERT_TRUE(exact.loaded()) << exact.log();
  capped.step();
  exact.step();
  EXPECT_GT(largestDifference(capped, exact), 1e-6);
  // The node holds no linear solver: the CG is the solver's own, and so is its warning.
  bool found = false;
  for (const Message& m : capped.scene().log().messages())
    found = found || (m.componentPath == "/root/Body/solver" &&
                      m.text.find("its conjugate gradient") != std::string::npos);
  EXPECT_TRUE(found) << capped.log();
}

}  // namespace
}  // namespace stroma::test
