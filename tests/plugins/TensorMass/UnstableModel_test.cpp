// SPDX-License-Identifier: MIT
// A tensor-mass model integrated explicitly above its stability bound (issue 4, bad input: "a
// model that has become unstable stops the run with exit code 1 and says where"): `stroma run`
// on the beam of scenes/tensormass/ExplicitBeam.scn, coarser, with central differences at 3
// times the bound that the solver estimates (output criticalTimeStep), warns that dt is above
// the bound, then stops at the first non-finite position with exit code 1, naming the step and
// the state. Just below the bound, the same run goes to its end without a word.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "core/Data.h"
#include "plugins/SolidMechanics/FemTestScenes.h"
#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {
namespace {

/// A soft beam (0.15 x 0.10 x 0.07 m, E = 30 kPa, nu = 0.45, 1000 kg/m^3) clamped at x = 0,
/// sagging under gravity: 6 x 4 x 3 cells split into 432 tetrahedra, lumped masses, central
/// differences with mass damping.
std::string beamScene(const std::string& forceField, double dt) {
  std::ostringstream xml;
  xml.precision(17);
  xml << R"(<Node name="root" dt=")" << dt << R"(" gravity="0 -9.81 0">
  <Node name="Beam">
    <CentralDifferenceSolver name="odeSolver" rayleighMass="5"/>
    <RegularGridTopology name="grid" n="7 5 4" min="0 0 0" max="0.15 0.10 0.07"/>
    <TetrahedronSetTopologyContainer name="topology"/>
    <Hexa2TetraTopologicalMapping name="split" input="@grid" output="@topology"/>
    <MechanicalObject name="dofs"/>
    <DiagonalMass name="mass" massDensity="1000"/>
    <)"
      << forceField << R"( name="elasticity" youngModulus="3e4" poissonRatio="0.45"/>
    <BoxROI name="clamp" box="-0.001 -0.001 -0.001  0.001 0.101 0.071" position="@dofs.rest_position"/>
    <FixedConstraint name="fixed" indices="@clamp.indices"/>
  </Node>
</Node>)";
  return xml.str();
}

/// The solver's stability bound, estimated at the first step of a run well below it.
double criticalTimeStep(const std::string& forceField) {
  Runtime runtime;
  Scene scene(runtime);
  if (!scene.loadString(beamScene(forceField, 1e-5))) {
    ADD_FAILURE() << describe(scene.log());
    return 0;
  }
  EXPECT_TRUE(scene.step()) << describe(scene.log());
  auto* solver = objectAt<Base>(scene, "/root/Beam/odeSolver");
  const auto* bound =
      solver ? dynamic_cast<const Data<double>*>(solver->findData("criticalTimeStep")) : nullptr;
  EXPECT_NE(bound, nullptr);
  return bound ? bound->value() : 0;
}

struct CliRun {
  int exitCode = -1;
  std::string output;  ///< stdout and stderr
};

CliRun runCli(const std::string& xml, int steps) {
  TempDir dir;
  const auto scene = dir.write("beam.scn", xml);
  const auto log = dir.path() / "log.txt";
  const std::string command = std::string("\"") + STROMA_CLI + "\" run \"" + scene.string() +
                              "\" -n " + std::to_string(steps) + " > \"" + log.string() + "\" 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

class UnstableModel : public testing::TestWithParam<std::string> {};

TEST_P(UnstableModel, StopsWithExitCode1NamingTheStepAndTheState) {
  const double bound = criticalTimeStep(GetParam());
  ASSERT_GT(bound, 0);
  // The Courant estimate h < d_min sqrt(rho / (lambda + 2 mu)) = 0.0233 m x 0.094 s/m =
  // 2.2e-3 s for this mesh, up to a factor of order one.
  EXPECT_GT(bound, 0.2 * 2.2e-3);
  EXPECT_LT(bound, 2.0 * 2.2e-3);

  constexpr int kSteps = 1000;
  const CliRun run = runCli(beamScene(GetParam(), 3 * bound), kSteps);
  EXPECT_EQ(run.exitCode, 1) << run.output;
  // The warning at the first step, with the bound.
  char bound4[32];
  std::snprintf(bound4, sizeof bound4, "%.4g s", bound);
  EXPECT_NE(run.output.find("warning: /root/Beam/odeSolver (CentralDifferenceSolver): dt = "),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find(std::string("is above the stability bound of central differences, ") +
                            bound4),
            std::string::npos)
      << run.output;
  // The error: where and when.
  std::smatch match;
  ASSERT_TRUE(std::regex_search(
      run.output, match,
      std::regex("error: /root/Beam/odeSolver \\(CentralDifferenceSolver\\): the simulation "
                 "diverged at time [0-9.e+-]+: position after step ([0-9]+) of /root/Beam/dofs "
                 "is not finite at index [0-9]+")))
      << run.output;
  EXPECT_LT(run.output.find("is above the stability bound"), run.output.find("error:"));
  const int step = std::stoi(match[1]);
  EXPECT_GT(step, 1);
  EXPECT_LT(step, kSteps);
  EXPECT_NE(run.output.find("stroma: the simulation failed at step " + std::to_string(step)),
            std::string::npos)
      << run.output;
  std::printf("[ unstable ] %s: bound %.4g s, dt = 3 x bound: diverged at step %d\n",
              GetParam().c_str(), bound, step);
}

TEST_P(UnstableModel, RunsToTheEndSilentlyJustBelowTheBound) {
  const double bound = criticalTimeStep(GetParam());
  ASSERT_GT(bound, 0);
  const CliRun run = runCli(beamScene(GetParam(), 0.9 * bound), 300);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("error"), std::string::npos) << run.output;
}

INSTANTIATE_TEST_SUITE_P(TensorMass, UnstableModel,
                         testing::Values("TetrahedralTensorMassForceField",
                                         "TetrahedralStVKTensorMassForceField"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(std::string("Tetrahedral").size());
                         });

}  // namespace
}  // namespace stroma::test
