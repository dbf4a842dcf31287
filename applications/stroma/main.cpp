// SPDX-License-Identifier: MIT
// The `stroma` command: run, check and document scenes.
#include <iostream>
#include <string>
#include <vector>

#include "CommandLine.h"
#include "core/NameSuggestions.h"
#include "core/Runtime.h"

namespace {

const char* kHelp = R"(Stroma: interactive simulation of deformable bodies.

Usage:
  stroma run SCENE [options]        load a scene, run it, print a timing summary
      -n STEPS                      number of time steps (default 100)
      --dt DT                       time step, overriding the scene's (s)
      --threads N                   threads for parallel element loops (default: all cores)
      --export-state FILE           write every mechanical state at the end (state format:
                                    docs/state-format.md)
      --export-every K              ... and also every K steps (with step 0)
  stroma check SCENE [options]      load a scene and report every problem, without running it
  stroma check --stability [--quick] [--csv FILE] [--save-scenes DIR]
                                    the stability suite: each model (linear, corotational and
                                    hyperelastic tetrahedra, tensor-mass, hexahedra) with each
                                    solver (implicit Euler + CG or LDL, static, central
                                    differences, symplectic Euler, RK4) on extreme cases (Young's
                                    modulus 1e2..1e10 Pa, Poisson 0.3..0.4999, dt 1e-5..1 s,
                                    slivers, inverted elements, a load of 100 E, an impact):
                                    stable / stalled / refused / diverged, with the reason;
                                    exit code 1 only when a case fails to load or throws;
                                    --save-scenes writes each case's scene, for stroma run
  stroma bench STUDY.xml [options]  run a study (scenes x models, resolutions, solvers, time
                                    steps), write DIR/STUDY.csv and DIR/STUDY.png (error
                                    against run time); format: bench/studies/README.md
      --quick                       only the study's quick rows and steps
      --output DIR                  where the CSV and the plot go (default bench-results)
      --threads N                   threads per scene (default 1; 0: all cores)
      --data-path DIR               as for run
      --save-scenes                 also write each row's scene as DIR/STUDY-scenes/rowN.scn
  stroma list [--plugin NAME]       available components, by plugin
  stroma doc COMPONENT              every field of a component: type, default, unit, help
  stroma plugin-index LIB --output FILE
                                    write the component index of a plugin library (build step)
  stroma --version | --help

Options of run and check:
  --data-path DIR                   also search DIR for relative file names (repeatable; the
                                    environment variable STROMA_DATA_PATH does the same)
  --log-json FILE                   also write every message as JSON lines to FILE
  --verbose                         print info messages too

Plugins are found in STROMA_PLUGIN_PATH, then beside the Stroma library.
Exit codes: 0 success, 1 simulation failure, 2 bad input or usage.
)";

}  // namespace

int main(int argc, char** argv) {
  using namespace stroma::cli;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    std::cerr << kHelp;
    return kBadInput;
  }
  const std::string command = args.front();
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << kHelp;
      return kSuccess;
    }
    if (command == "--version") {
      std::cout << "stroma " << stroma::stromaVersion() << '\n';
      return kSuccess;
    }
    if (command == "run") return runCommand(rest);
    if (command == "check") return checkCommand(rest);
    if (command == "bench") return benchCommand(rest);
    if (command == "list") return listCommand(rest);
    if (command == "doc") return docCommand(rest);
    if (command == "plugin-index") return pluginIndexCommand(rest);
  } catch (const std::exception& e) {
    // A bug, not bad input: say so plainly rather than abort.
    std::cerr << "stroma: internal error: " << e.what() << '\n';
    return kSimulationFailure;
  }
  std::string text = "unknown command '" + command + "'";
  const auto near = stroma::nearestNames(
      command, {"run", "check", "bench", "list", "doc", "plugin-index", "--help", "--version"});
  if (!near.empty()) text += "; did you mean " + stroma::quotedList(near) + "?";
  return usageError(text);
}
