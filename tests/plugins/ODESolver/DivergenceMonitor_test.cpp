// SPDX-License-Identifier: MIT
// Divergence detection at run time (DivergenceMonitor.h): each kind is found on a scene made to
// diverge, and reported with the step, the solver and the worst vertex. With
// onDivergence="stop" it is an error (the step fails, `stroma run` exits with 1); with "warn" a
// single warning and the run goes on, and when the state grew by orders of magnitude (energy
// growth) the run still ends as a failure (exit code 1). A run that does not diverge reports
// nothing.
#include <gtest/gtest.h>

#include <sstream>

#include "SolverTestSupport.h"
#include "support/CliRun.h"

namespace stroma::test {
namespace {

struct Diverging {
  std::string name;
  std::string xml;     ///< the scene, with MODE where onDivergence goes
  int steps;           ///< the step where the divergence is found
  std::string kind;    ///< "divergence (...) at step N"
  std::string vertex;  ///< "worst vertex: vertex I of /root/Body/dofs"
  std::string field;
  bool failsRun;  ///< whether a warn-mode run still ends as a failure (the state blew up)
};

std::string withMode(const std::string& xml, const std::string& mode) {
  std::string text = xml;
  for (std::size_t at = text.find("MODE"); at != std::string::npos; at = text.find("MODE", at))
    text.replace(at, 4, mode);
  return text;
}

// Points 0..5 along x, each on an anchor spring, neighbours joined by stiff springs; point 5
// starts 0.1 m off along y.
std::string chainScene(const std::string& solvers, const std::string& anchorExtra = "",
                       double dt = 0.1) {
  std::ostringstream xml;
  xml << R"(<Node name="root" dt=")" << dt << R"(" gravity="0 0 0"><Node name="Body">)" << solvers
      << R"(
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0  5 0.1 0"
                      rest_position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0  5 0 0"/>
    <UniformMass name="mass" vertexMass="1"/>
    <TestAnchorForceField name="anchor" stiffness="100 100 100" )"
      << anchorExtra << R"(/>
    <TestSpringForceField name="springs" springs="0 1 1 2 2 3 3 4 4 5" stiffness="1e4"/>
  </Node></Node>)";
  return xml.str();
}

std::vector<Diverging> divergingScenes() {
  return {
      // Forward Euler on undamped oscillators is above its bound at any dt: the energy doubles
      // each step at omega h = 1, 1024 times per window of 10 steps; the fourth window ends at
      // step 40. The state then is 2^20 times the initial one (eight steps turn it once): the
      // largest velocity is point 1's.
      {"EnergyGrowth",
       oscillatorScene(
           R"(<EulerExplicitSolver name="ode" symplectic="false" onDivergence="MODE"/>)", 100, 1.0,
           "1 0 0  0 2 0", "0 0 0  0 0 5", 0.1),
       40, "divergence (energy growth) at step 40, time 4 s",
       "worst vertex: vertex 1 of /root/Body/dofs", "energyGrowth", true},
      // The same at omega h = 50: the state is multiplied by about 50 at each step, in a mode
      // that turns by nearly a quarter of a period per step (T alone alternates between large
      // and small growths). The sum of T over two steps grows 5, 2e3, 17, 5e3... times: the
      // third growth in a row is at step 5.
      {"BlowUp",
       oscillatorScene(
           R"(<EulerExplicitSolver name="ode" symplectic="false" onDivergence="MODE"/>)", 1e4, 4.0,
           "1 0 0  0 2 0", "0 0 0  0 0 0", 1.0),
       5,
       "divergence (energy growth) at step 5, time 5 s: the kinetic energy of two consecutive "
       "steps grew",
       "worst vertex: vertex ", "energyGrowth", true},
      // One CG iteration on the stiff chain: far from the solution.
      {"LinearSolve", chainScene(R"(<EulerImplicitSolver name="ode" onDivergence="MODE"/>
                     <CGLinearSolver name="cg" iterations="1" tolerance="1e-12"/>)"),
       1,
       "divergence (unconverged linear solve) at step 1, time 0.1 s: the linear solver "
       "/root/Body/cg stopped after 1 iterations",
       "worst vertex: vertex ", "maxLinearResidual", false},
      // A tangent of the wrong sign: every Newton direction raises the residual.
      {"StaticNewtonStall",
       chainScene(R"(<StaticSolver name="ode" newton_iterations="5" onDivergence="MODE"/>
                     <SparseLDLSolver/>)",
                  R"(tangentScale="-1")"),
       1,
       "divergence (stalled Newton iteration) at step 1, time 0.1 s: no step along the Newton "
       "direction",
       "worst vertex: vertex ", "maxNbIterationsLineSearch", false},
      {"ImplicitEulerNewtonStall",
       chainScene(R"(<EulerImplicitSolver name="ode" newtonIterations="5" onDivergence="MODE"/>
                     <SparseLDLSolver/>)",
                  R"(tangentScale="-1")", 1.0),
       1,
       "divergence (stalled Newton iteration) at step 1, time 1 s: Newton stopped after 5 linear "
       "solves",
       "worst vertex: vertex ", "newtonIterations", false},
  };
}

std::string caseName(const testing::TestParamInfo<Diverging>& info) { return info.param.name; }
void PrintTo(const Diverging& d, std::ostream* out) { *out << d.name; }

class DivergenceKinds : public testing::TestWithParam<Diverging> {};

TEST_P(DivergenceKinds, StopModeStopsWithTheStepTheSolverAndTheWorstVertex) {
  const Diverging& d = GetParam();
  SolverScene s(withMode(d.xml, "stop"));
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 1; n < d.steps; ++n) ASSERT_TRUE(s.step()) << "step " << n << "\n" << s.log();
  EXPECT_FALSE(s.step()) << s.log();
  const Message m = findError(s.scene().log(), "divergence (");
  EXPECT_NE(m.text.find(d.kind), std::string::npos) << m.text;
  EXPECT_NE(m.text.find(d.vertex), std::string::npos) << m.text;
  EXPECT_NE(m.text.find("The run stops"), std::string::npos) << m.text;
  EXPECT_EQ(m.componentPath, "/root/Body/ode");
  EXPECT_EQ(m.field, d.field);
}

TEST_P(DivergenceKinds, WarnModeWarnsOnceAndGoesOn) {
  const Diverging& d = GetParam();
  SolverScene s(withMode(d.xml, "warn"));
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 1; n <= d.steps + 1; ++n) ASSERT_TRUE(s.step()) << "step " << n << "\n" << s.log();
  int found = 0;
  for (const Message& m : s.scene().log().messages()) {
    EXPECT_NE(m.level, MessageLevel::error) << m.text;
    if (m.text.find("divergence (") == std::string::npos) continue;
    ++found;
    EXPECT_EQ(m.level, MessageLevel::warning);
    EXPECT_NE(m.text.find(d.kind), std::string::npos) << m.text;
    EXPECT_NE(m.text.find(d.vertex), std::string::npos) << m.text;
    EXPECT_NE(m.text.find("The run goes on"), std::string::npos) << m.text;
    EXPECT_EQ(m.failsRun, d.failsRun) << m.text;
  }
  EXPECT_EQ(found, 1) << s.log();
  EXPECT_EQ(s.scene().log().runFailureCount(), d.failsRun ? 1u : 0u) << s.log();
}

INSTANTIATE_TEST_SUITE_P(ODESolver, DivergenceKinds, testing::ValuesIn(divergingScenes()),
                         caseName);

TEST(DivergenceMonitor, ABoundedRunReportsNothing) {
  // Symplectic Euler below its bound (0.2 s), implicit Euler with CG, static Newton: no report.
  for (
      const std::string solvers :
      {R"(<EulerExplicitSolver name="ode" onDivergence="stop"/>)",
       R"(<EulerImplicitSolver name="ode" onDivergence="stop"/><CGLinearSolver iterations="100" tolerance="1e-10" threshold="1e-30"/>)",
       R"(<StaticSolver name="ode" newton_iterations="5" onDivergence="stop"/><SparseLDLSolver/>)"}) {
    SCOPED_TRACE(solvers);
    SolverScene s(oscillatorScene(solvers, 100, 1.0, "1 0 0  0 2 0", "0 0 0  3 0 0", 0.05));
    ASSERT_TRUE(s.loaded()) << s.log();
    for (int n = 0; n < 60; ++n) ASSERT_TRUE(s.step()) << s.log();
    EXPECT_EQ(s.scene().log().count(MessageLevel::warning), 0u) << s.log();
  }
}

TEST(DivergenceMonitor, BadSettingsAreErrorsNamingTheField) {
  for (const auto& [attribute, field] :
       {std::pair<std::string, std::string>{R"(onDivergence="halt")", "onDivergence"},
        {R"(energyGrowth="-1")", "energyGrowth"},
        {R"(energyWindow="0")", "energyWindow"}}) {
    SCOPED_TRACE(attribute);
    SolverScene s(
        oscillatorScene("<EulerExplicitSolver name=\"ode\" " + attribute + "/>", 100, 1.0));
    EXPECT_FALSE(s.loaded());
    bool named = false;
    for (const Message& m : s.scene().log().messages())
      named = named || (m.level == MessageLevel::error && m.field == field);
    EXPECT_TRUE(named) << s.log();
  }
}

TEST(DivergenceMonitor, AnExplicitSolverInStopModeRefusesATimeStepAboveItsBound) {
  // omega = 10 rad/s: central differences are stable for dt < 0.2 s.
  SolverScene s(oscillatorScene(R"(<CentralDifferenceSolver name="ode" onDivergence="stop"/>)", 100,
                                1.0, "1 0 0", "0 0 0", 0.25));
  ASSERT_TRUE(s.loaded()) << s.log();
  EXPECT_FALSE(s.step());
  const Message m = findError(s.scene().log(), "divergence (time step above the stability bound)");
  EXPECT_NE(m.text.find("at step 1"), std::string::npos) << m.text;
  EXPECT_NE(m.text.find("dt = 0.25 s is above the stability bound of central differences, 0.2 s"),
            std::string::npos)
      << m.text;
  EXPECT_NE(m.text.find("worst vertex: vertex 0 of /root/Body/dofs (|highest mode|"),
            std::string::npos)
      << m.text;
  EXPECT_EQ(m.field, "dt");
  EXPECT_EQ(s.position(0), Vec3d(1, 0, 0));  // refused before anything moved
  s.step();  // a solver that reported an error is off for the rest of the run
  EXPECT_EQ(s.position(0), Vec3d(1, 0, 0));
}

TEST(DivergenceMonitor, EnergyGrowthIsNotTakenForAnImpactOrALoad) {
  // Implicit Euler: a stiff chain hit at its end (point 5 moved 0.1 m at once): the kinetic
  // energy jumps and decays, it never grows three windows in a row.
  SolverScene s(chainScene(R"(<EulerImplicitSolver name="ode" onDivergence="stop"/>
                              <SparseLDLSolver/>)",
                           "", 0.01));
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 100; ++n) ASSERT_TRUE(s.step()) << s.log();
  // Symplectic Euler under gravity from rest: T grows like t^2, below the criterion.
  SolverScene fall(R"(<Node name="root" dt="0.01" gravity="0 -9.81 0"><Node name="Body">
    <EulerExplicitSolver name="ode" onDivergence="stop"/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <UniformMass vertexMass="1"/></Node></Node>)");
  ASSERT_TRUE(fall.loaded()) << fall.log();
  for (int n = 0; n < 200; ++n) ASSERT_TRUE(fall.step()) << fall.log();
  EXPECT_EQ(fall.scene().log().count(MessageLevel::warning), 0u) << fall.log();
}

// `stroma run` on real components: exit code 1 in stop mode, 0 with a warning in warn mode.
int runCli(const std::string& xml, int steps, std::string& output) {
  const CliRun run = runScene(STROMA_CLI, xml, steps);
  output = run.output;
  return run.exitCode;
}

// A chain of 6 points on springs, point 0 fixed, point 5 pulled 0.1 m off at the start.
std::string springChain(const std::string& solvers, double dt) {
  return R"(<Node name="root" dt=")" + std::to_string(dt) + R"(" gravity="0 0 0">
  <Node name="Body">
    )" + solvers +
         R"(
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0  5 0.1 0"
                      rest_position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0  5 0 0"/>
    <UniformMass vertexMass="1"/>
    <SpringForceField spring="0 1 1e4 0 1  1 2 1e4 0 1  2 3 1e4 0 1  3 4 1e4 0 1  4 5 1e4 0 1"/>
    <FixedConstraint indices="0"/>
  </Node>
</Node>)";
}

TEST(StromaRun, ExitsWith1OnADivergenceInStopModeAndInWarnModeWhenTheStateGrew) {
  // Stop mode ends the run at the divergence. Warn mode goes on; it still exits with 1 when
  // the state grew by orders of magnitude (energy growth), and with 0 after a linear solve
  // stopped unconverged (the state may be fine).
  struct CliCase {
    std::string solvers, kind;
    double dt;
    int steps;
    int warnExitCode;
  };
  for (const CliCase& c :
       {CliCase{R"(<EulerExplicitSolver symplectic="false" onDivergence="MODE"/>)",
                "divergence (energy growth) at step", 0.01, 60, 1},
        CliCase{R"(<EulerImplicitSolver onDivergence="MODE"/><CGLinearSolver iterations="1"/>)",
                "divergence (unconverged linear solve) at step 1", 0.1, 3, 0}}) {
    SCOPED_TRACE(c.kind);
    std::string output;
    EXPECT_EQ(runCli(withMode(springChain(c.solvers, c.dt), "stop"), c.steps, output), 1) << output;
    EXPECT_NE(output.find("error: /root/Body/"), std::string::npos) << output;
    EXPECT_NE(output.find(c.kind), std::string::npos) << output;
    EXPECT_NE(output.find("worst vertex: vertex "), std::string::npos) << output;
    EXPECT_EQ(runCli(withMode(springChain(c.solvers, c.dt), "warn"), c.steps, output),
              c.warnExitCode)
        << output;
    EXPECT_NE(output.find("warning: /root/Body/"), std::string::npos) << output;
    EXPECT_NE(output.find(c.kind), std::string::npos) << output;
    EXPECT_EQ(output.find("error:"), std::string::npos) << output;
    EXPECT_EQ(output.find("the run went on after its state diverged") != std::string::npos,
              c.warnExitCode == 1)
        << output;
  }
}

TEST(StromaRun, ABlowUpIsCaughtWithinFiveStepsAndNeverExits0) {
  // The issue's case: symplectic Euler at dt = 0.5 s on a stiff hexahedral grid whose bound
  // is about 1e-5 s (the load-time warning says so). Before the blow-up check, 20 steps
  // ended with positions of 1e193 m and exit code 0.
  const std::string grid = R"(<Node name="root" dt="0.5" gravity="0 -9.81 0">
  <Node name="Grid">
    <EulerExplicitSolver onDivergence="MODE"/>
    <RegularGridTopology name="grid" min="0 0 0" max="0.1 0.1 0.1" n="4 4 4"/>
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="0.1"/>
    <HexahedronFEMForceField method="large" youngModulus="1e6" poissonRatio="0.3"/>
    <FixedConstraint indices="0 1 2 3"/>
  </Node>
</Node>)";
  auto stepOfReport = [](const std::string& output) {
    const std::string marker = "divergence (energy growth) at step ";
    const std::size_t at = output.find(marker);
    return at == std::string::npos ? -1 : std::atoi(output.c_str() + at + marker.size());
  };
  std::string output;
  EXPECT_EQ(runCli(withMode(grid, "warn"), 20, output), 1) << output;
  EXPECT_NE(output.find("is above the stability bound"), std::string::npos) << output;
  const int warned = stepOfReport(output);
  EXPECT_GE(warned, 1) << output;
  EXPECT_LE(warned, 5) << output;
  EXPECT_NE(output.find("but ends as a failure"), std::string::npos) << output;
  EXPECT_NE(output.find("the run went on after its state diverged"), std::string::npos) << output;

  // In stop mode the time step is refused before anything moves; without that refusal
  // (no bound check: the state's first steps) the blow-up check stops it within 5 steps.
  EXPECT_EQ(runCli(withMode(grid, "stop"), 20, output), 1) << output;
  EXPECT_NE(output.find("error: /root/Grid/"), std::string::npos) << output;
}

TEST(StromaRun, ExitsWith1WhenStaticNewtonStallsInStopMode) {
  // A very soft corotational beam (E = 100 Pa) hanging under its weight, in one load step: the
  // corotational tangent leaves out the rotations' derivative, and at this deformation no step
  // along its Newton direction lowers the residual (the stability suite's case).
  const std::string beam = R"(<Node name="root" dt="0.001" gravity="0 -9.81 0">
  <Node name="Beam">
    <StaticSolver newton_iterations="20" onDivergence="MODE"/>
    <SparseLDLSolver/>
    <RegularGridTopology name="grid" min="0 0 0" max="0.1 0.05 0.05" n="5 2 2"/>
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="0.25"/>
    <HexahedronFEMForceField method="large" youngModulus="100" poissonRatio="0.3"/>
    <FixedConstraint indices="0 5 10 15"/>
  </Node>
</Node>)";
  std::string output;
  EXPECT_EQ(runCli(withMode(beam, "stop"), 3, output), 1) << output;
  EXPECT_NE(output.find("error: /root/Beam/"), std::string::npos) << output;
  EXPECT_NE(output.find("divergence (stalled Newton iteration) at step 1"), std::string::npos)
      << output;
  EXPECT_NE(output.find("worst vertex: vertex "), std::string::npos) << output;
  EXPECT_EQ(runCli(withMode(beam, "warn"), 3, output), 0) << output;
  EXPECT_NE(output.find("divergence (stalled Newton iteration) at step 1"), std::string::npos)
      << output;
  EXPECT_EQ(output.find("error:"), std::string::npos) << output;
}

TEST(StromaRun, ExitsWith1OnNonFiniteValuesInBothModes) {
  // Central differences at 100 times their bound, allowed to run in warn mode: the state
  // overflows; non-finite values stop the run whatever onDivergence says.
  std::string output;
  EXPECT_EQ(
      runCli(springChain(R"(<CentralDifferenceSolver onDivergence="warn" energyGrowth="0"/>)", 2.0),
             400, output),
      1)
      << output;
  EXPECT_NE(output.find("of /root/Body/dofs is not finite at index "), std::string::npos) << output;
}

}  // namespace
}  // namespace stroma::test
