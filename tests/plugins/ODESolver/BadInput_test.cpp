// SPDX-License-Identifier: MIT
// Every ODE solver refuses a time step <= 0 and stops a run whose state becomes NaN or
// infinite, with an error naming the step and the state; `stroma run` then exits with 1.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "SolverTestSupport.h"
#include "support/CliRun.h"

namespace stroma::test {
namespace {

struct SolverCase {
  std::string className;
  std::string xml;  ///< the solver components
};

std::string caseName(const testing::TestParamInfo<SolverCase>& info) {
  return info.param.className;
}
void PrintTo(const SolverCase& c, std::ostream* out) { *out << c.xml; }

class EverySolver : public testing::TestWithParam<SolverCase> {};

TEST_P(EverySolver, RefusesAZeroTimeStep) {
  SolverScene s(oscillatorScene(GetParam().xml, 100.0, 1.0, "1 0 0", "0 0 0", 0.0));
  ASSERT_TRUE(s.loaded()) << s.log();
  EXPECT_FALSE(s.step());
  const Message m = findError(s.scene().log(), "time step");
  EXPECT_NE(m.text.find("dt = 0"), std::string::npos) << s.log();
  EXPECT_EQ(m.field, "dt");
  EXPECT_EQ(m.componentClass, GetParam().className);
  EXPECT_EQ(s.position(0), Vec3d(1, 0, 0));  // nothing moved
}

TEST_P(EverySolver, StopsAtANonFiniteStateNamingTheStepAndTheState) {
  SolverScene s(oscillatorScene(GetParam().xml, 100.0, 1.0, "1 0 0  2 0 0", "0 0 0  0 0 0", 0.01));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  s.state().writeCoord(VecId::position())[1].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(s.step());
  // Step 3 ends at 0.03 s: the time of the state that is not finite.
  const Message m = findError(s.scene().log(), "the simulation diverged at time 0.030000: ");
  EXPECT_NE(m.text.find("after step 3 of /root/Body/dofs is not finite at index 1"),
            std::string::npos)
      << s.log();
  EXPECT_EQ(m.componentClass, GetParam().className);
}

INSTANTIATE_TEST_SUITE_P(
    ODESolver, EverySolver,
    testing::Values(SolverCase{"EulerExplicitSolver", "<EulerExplicitSolver/>"},
                    SolverCase{"EulerImplicitSolver", "<EulerImplicitSolver/><SparseLDLSolver/>"},
                    SolverCase{"CentralDifferenceSolver", "<CentralDifferenceSolver/>"},
                    SolverCase{"RungeKutta4Solver", "<RungeKutta4Solver/>"},
                    SolverCase{"NewmarkImplicitSolver",
                               "<NewmarkImplicitSolver/><SparseLDLSolver/>"},
                    SolverCase{"StaticSolver", "<StaticSolver/><SparseLDLSolver/>"}),
    caseName);

TEST(ImplicitSolvers, NeedALinearSolver) {
  for (const std::string solver :
       {"EulerImplicitSolver", "NewmarkImplicitSolver", "StaticSolver"}) {
    SolverScene s(oscillatorScene("<" + solver + "/>", 100.0, 1.0));
    EXPECT_FALSE(s.loaded());
    const Message m = findError(s.scene().log(), "needs a linear solver");
    EXPECT_EQ(m.componentClass, solver) << s.log();
    EXPECT_EQ(m.field, "linearSolver");
  }
}

TEST(EverySolverKind, WithoutAStateWarnsOnceThatItIntegratesNothing) {
  for (const std::string solvers :
       {"<EulerExplicitSolver/>", "<EulerImplicitSolver/><CGLinearSolver/>",
        "<StaticSolver/><SparseLDLSolver/>", "<RungeKutta4Solver/>"}) {
    SCOPED_TRACE(solvers);
    // The solver sits in a sibling of the body's node: nothing at or below it moves.
    SolverScene s(R"(<Node name="root" dt="0.01"><Node name="Solvers">)" + solvers +
                  R"(</Node><Node name="Body"><MechanicalObject position="0 0 0"/>
                  <UniformMass vertexMass="1"/></Node></Node>)");
    ASSERT_TRUE(s.loaded()) << s.log();
    for (int n = 0; n < 3; ++n) ASSERT_TRUE(s.step()) << s.log();
    ASSERT_EQ(s.scene().log().count(MessageLevel::warning), 1u) << s.log();
    for (const Message& m : s.scene().log().messages())
      if (m.level == MessageLevel::warning) {
        EXPECT_EQ(m.componentPath.rfind("/root/Solvers/", 0), 0u) << m.componentPath;
        EXPECT_NE(m.text.find("no mechanical state in /root/Solvers or below"), std::string::npos)
            << m.text;
      }
  }
}

// `stroma run` on a scene that overflows at the first step, and on one with dt = 0.
int runCli(const std::string& xml, std::string& output) {
  const CliRun run = runScene(STROMA_CLI, xml, 5);
  output = run.output;
  return run.exitCode;
}

TEST(StromaRun, ExitsWith1WhenTheSimulationDiverges) {
  // a = 1e300 N / 1e-300 kg overflows: the velocity and then the position are infinite.
  std::string output;
  const int code = runCli(R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <Node name="Body">
    <EulerExplicitSolver/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass vertexMass="1e-300"/>
    <ConstantForceField force="1e300 0 0"/>
  </Node>
</Node>)",
                          output);
  EXPECT_EQ(code, 1) << output;
  EXPECT_NE(output.find("position after step 1 of /root/Body/dofs is not finite"),
            std::string::npos)
      << output;
}

TEST(StromaRun, ExitsWith1WhenTheTimeStepIsZero) {
  std::string output;
  const int code = runCli(R"(<Node name="root" dt="0" gravity="0 0 0">
  <Node name="Body">
    <RungeKutta4Solver/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass vertexMass="1"/>
  </Node>
</Node>)",
                          output);
  EXPECT_EQ(code, 1) << output;
  EXPECT_NE(output.find("dt = 0"), std::string::npos) << output;
}

}  // namespace
}  // namespace stroma::test
