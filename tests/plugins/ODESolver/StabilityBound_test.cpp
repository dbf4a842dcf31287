// SPDX-License-Identifier: MIT
// The stability bound of the explicit solvers (output `criticalTimeStep`, c / omega_max): exact
// on a harmonic oscillator, of the order of the Courant step d sqrt(rho / (lambda + 2 mu)) on a
// tetrahedral mesh, and a real bound there: central differences run bounded just below it and
// diverge just above it. A time step above it is warned about once, naming the bound.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "SolverTestSupport.h"

namespace stroma::test {
namespace {

double criticalStep(SolverScene& s, const std::string& solver) {
  return std::stod(s.field(solver, "criticalTimeStep"));
}

TEST(StabilityBound, IsExactOnAHarmonicOscillator) {
  // omega = sqrt(100 / 1) = 10 rad/s: 2 / omega = 0.2 s; RK4's 2 sqrt(2) / omega.
  for (const auto& [solver, bound] :
       {std::pair<std::string, double>{"CentralDifferenceSolver", 0.2},
        {"EulerExplicitSolver", 0.2},
        {"RungeKutta4Solver", 0.2 * std::sqrt(2.0)}}) {
    SCOPED_TRACE(solver);
    SolverScene s(oscillatorScene("<" + solver + " name=\"ode\"/>", 100, 1.0, "1 0.5 -2"));
    ASSERT_TRUE(s.loaded()) << s.log();
    EXPECT_EQ(criticalStep(s, "ode"), 0.0);  // not estimated before the first step
    ASSERT_TRUE(s.step()) << s.log();
    EXPECT_NEAR(criticalStep(s, "ode"), bound, 1e-12 * bound);
    EXPECT_EQ(s.scene().log().count(MessageLevel::warning), 0u) << s.log();
  }
}

TEST(StabilityBound, ATimeStepAboveItIsWarnedAboutOnceWithTheBound) {
  SolverScene s(oscillatorScene(R"(<CentralDifferenceSolver name="ode"/>)", 100, 1.0, "1 0 0",
                                "0 0 0", 0.25));
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 3; ++n) s.step();
  ASSERT_EQ(s.scene().log().count(MessageLevel::warning), 1u) << s.log();
  for (const Message& m : s.scene().log().messages())
    if (m.level == MessageLevel::warning) {
      EXPECT_EQ(m.componentClass, "CentralDifferenceSolver");
      EXPECT_NE(m.text.find("dt = 0.25 s is above the stability bound of central differences, "
                            "0.2 s (= 2 / omega_max, omega_max = 10 rad/s"),
                std::string::npos)
          << m.text;
    }
}

// A linear elastic bar of 8 x 2 x 2 cubes of 0.05 m split into tetrahedra, clamped at x = 0,
// lumped masses, explicit central differences without damping, started from a small
// random-looking displacement (a constant force applied for the first steps).
std::string barScene(double dt) {
  std::ostringstream xml;
  xml.precision(17);
  xml << R"(<Node name="root" dt=")" << dt << R"(" gravity="0 -9.81 0"><Node name="Body">
    <CentralDifferenceSolver name="ode"/>
    <RegularGridTopology name="grid" min="0 0 0" max="0.4 0.1 0.1" n="9 3 3"/>
    <MechanicalObject name="dofs" position="@grid.position"/>
    <TetrahedronSetTopologyContainer name="tetrahedra"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@tetrahedra"/>
    <DiagonalMass name="mass" massDensity="1000"/>
    <TetrahedronFEMForceField method="small" youngModulus="1e5" poissonRatio="0.3"/>
    <BoxROI name="clamped" box="-0.01 -0.01 -0.01  0.01 0.11 0.11" position="@dofs.rest_position"/>
    <FixedConstraint indices="@clamped.indices"/>
  </Node></Node>)";
  return xml.str();
}

TEST(StabilityBound, IsTheCourantStepOfATetrahedralMeshAndARealBound) {
  SolverScene probe(barScene(1e-5));
  ASSERT_TRUE(probe.loaded()) << probe.log();
  ASSERT_TRUE(probe.step()) << probe.log();
  const double bound = criticalStep(probe, "ode");
  // Courant: d sqrt(rho / (lambda + 2 mu)) with d = 0.05 m, the cube edge (the tetrahedra's
  // shortest edge); lambda + 2 mu = E (1 - nu) / ((1 + nu)(1 - 2 nu)).
  const double nu = 0.3, modulus = 1e5 * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double courant = 0.05 * std::sqrt(1000 / modulus);
  std::printf(
      "[ stability] bar: 2 / omega_max = %.4g s, Courant d sqrt(rho / (lambda + 2 mu)) "
      "= %.4g s\n",
      bound, courant);
  EXPECT_GT(bound, 0.2 * courant);
  EXPECT_LT(bound, 2.0 * courant);

  // 2000 steps at 0.95 of the bound stay bounded; at 1.05 the stiffest mode grows until the
  // run stops on a non-finite value.
  for (const double factor : {0.95, 1.05}) {
    SCOPED_TRACE(factor);
    SolverScene s(barScene(factor * bound));
    ASSERT_TRUE(s.loaded()) << s.log();
    bool finite = true;
    double largest = 0;
    for (int n = 0; n < 2000 && finite; ++n) {
      finite = s.step();
      for (const Vec3d& x : s.state().readCoord(VecId::position()))
        largest = std::max(largest, x.norm());
    }
    if (factor < 1) {
      EXPECT_TRUE(finite) << s.log();
      EXPECT_LT(largest, 1.0);  // the bar is 0.4 m long and sags by millimetres
      EXPECT_EQ(s.scene().log().count(MessageLevel::warning), 0u) << s.log();
    } else {
      EXPECT_TRUE(!finite || largest > 1e3) << "largest |x| " << largest;
      EXPECT_GE(s.scene().log().count(MessageLevel::warning), 1u) << s.log();
    }
  }
}

}  // namespace
}  // namespace stroma::test
