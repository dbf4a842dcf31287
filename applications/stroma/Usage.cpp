// SPDX-License-Identifier: MIT
#include "Usage.h"

#include <algorithm>

namespace stroma::cli {

namespace {

struct CommandHelp {
  std::string_view name;
  std::string_view synopsis;       ///< the command line(s) and what they do
  bool takesSceneOptions = false;  ///< --data-path, --log-json, --verbose
};

// clang-format off
const CommandHelp kCommands[] = {
    {"run", R"(  stroma run SCENE [options]        load a scene, run it, print a timing summary; SCENE may be
                                    a robot's .urdf (in a default scene: gravity -z, implicit
                                    solver, the base fixed unless its root joint floats)
      -n STEPS                      number of time steps (default 100)
      --dt DT                       time step, overriding the scene's (s)
      --threads N                   threads for parallel element loops (default: all cores)
      --export-state FILE           write every mechanical state at the end (state format:
                                    docs/state-format.md)
      --export-every K              ... and also every K steps (with step 0)
      --export-data PATH.FIELD      ... with this Data in each snapshot (repeatable), e.g.
                                    /root/Probe/dofs.constraintForce
      --export-vtk DIR              write every mechanical state as VTU files for ParaView
                                    (DIR/<state path>_<step>.vtu, one .pvd per state) at
                                    step 0, every K steps of --export-every (default 1)
                                    and the last step: positions, cells of the state's
                                    topology, displacement, velocity, von Mises stress
      --print PATH.FIELD            print this Data after each step (repeatable): the force
                                    a haptic device renders, a solver's iterations...
)", true},
    {"check", R"(  stroma check SCENE [options]      load a scene and report every problem, without running it
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
)", true},
    {"bench", R"(  stroma bench STUDY.xml [options]  run a study (scenes x models, resolutions, solvers, time
                                    steps), write DIR/STUDY.csv and DIR/STUDY.png (error
                                    against run time); format: bench/studies/README.md
      --quick                       only the study's quick rows and steps
      --output DIR                  where the CSV and the plot go (default bench-results)
      --threads N                   threads per scene (default 1; 0: all cores)
      --data-path DIR               as for run
      --save-scenes                 also write each row's scene as DIR/STUDY-scenes/rowN.scn
      --verbose                     print the scenes' info messages too
)", false},
    {"render", R"(  stroma render SCENE [options]     run a scene as `run` does and take pictures of it offscreen
                                    (OSMesa): DIR/frame_00000.png... at step 0, every K steps
                                    and at the last step
      -n STEPS                      number of time steps (default 100)
      --every K                     a frame every K steps (default: STEPS, so the first and
                                    the last frame only)
      --out DIR                     folder of the PNG frames (default frames; created)
      --size WxH                    picture size in pixels, 1 to 16384 each (default 640x480)
      --camera "px py pz lx ly lz"  eye and point looked at (default: the scene's
                                    InteractiveCamera, else a view of the whole scene)
      --color-map displacement|vonmises
                                    color the bodies by |x - x_rest| (m) or von Mises stress
                                    (Pa), with a legend; --no-legend leaves it out
      --show WORDS                  VisualStyle displayFlags words over the scene's, e.g.
                                    "showBehavior showWireframe" (a scene without VisualStyle
                                    nor visual model gets showForceFields)
      --video FILE.mp4              also pipe the frames to ffmpeg (must be on PATH; PNG files
                                    then only with --out)
      --dt DT, --threads N          as for run
    Exit codes: 0 frames written (a frame with nothing drawn is a warning), 1 a step failed,
    the state diverged, or a frame could not be written, 2 bad input (options, scene, output
    folder, size, color map with nothing to color, ffmpeg missing), all refused before the
    first step.
)", true},
    {"view", R"(  stroma view SCENE [options]       show a scene in a window and run it interactively
      --size WxH                    window size in pixels (default 1280x720)
      --animate                     start running (else paused, unless the scene's root
                                    says animate="1")
      --spring-stiffness K          stiffness of the mouse spring (N/m; default 1000 N/m
                                    per kg of the grabbed body)
      --threads N                   threads for parallel element loops (default: all cores)
      --frames N                    quit after N frames (scripts and tests)
      --data-path DIR, --verbose    as for run
    Keys and mouse (plugins/Viewer/README.md says the same):
      left drag                     orbit around the point looked at
      right or middle drag          pan
      wheel                         zoom
      shift + left press and drag   pull the body with a spring toward the mouse (the
                                    nearest vertex of the surface under the mouse;
                                    released with the button)
      space                         play / pause
      n or right arrow              one step (and pause)
      r                             reset: load the scene again from its file
      s                             screenshot: the picture without the text, as
                                    stroma-view-NNNN.png in the working folder
      h                             hide / show the text
      q or escape                   quit
    Needs a display (DISPLAY; else exit code 2) and GLFW 3 at build time (libglfw3-dev).
)", false},
    {"list", R"(  stroma list [--plugin NAME]       available components, by plugin
)", false},
    {"doc", R"(  stroma doc COMPONENT [--template T]
                                    every field of a component: type, default, unit, help
                                    (--template: of that template, as Rigid3d)
)", false},
    {"plugin-index", R"(  stroma plugin-index LIB --output FILE
                                    write the component index of a plugin library (build step)
)", false},
};
// clang-format on

constexpr std::string_view kHeader = "Stroma: interactive simulation of deformable bodies.\n";

constexpr std::string_view kSceneOptions = R"(Options of run and check:
  --data-path DIR                   also search DIR for relative file names (repeatable; the
                                    environment variable STROMA_DATA_PATH does the same)
  --log-json FILE                   also write every message as JSON lines to FILE
  --verbose                         print info messages too
)";

constexpr std::string_view kFooter = R"(
Plugins are found in STROMA_PLUGIN_PATH, then beside the Stroma library.
Exit codes: 0 success, 1 simulation failure (a step failed, or the state diverged and the scene
let the run go on), 2 bad input or usage.
)";

}  // namespace

const std::vector<std::string_view>& commandNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const CommandHelp& c : kCommands) out.push_back(c.name);
    return out;
  }();
  return names;
}

std::string generalUsage() {
  std::string text(kHeader);
  text += "\nUsage:\n";
  for (const CommandHelp& c : kCommands) text += c.synopsis;
  text += "  stroma COMMAND --help             the usage of one command\n";
  text += "  stroma --version | --help\n\n";
  text += kSceneOptions;
  text += kFooter;
  return text;
}

std::string commandUsage(std::string_view command) {
  for (const CommandHelp& c : kCommands) {
    if (c.name != command) continue;
    std::string text = "Usage:\n";
    text += c.synopsis;
    if (c.takesSceneOptions) {
      text += '\n';
      text += kSceneOptions;
    }
    text += kFooter;
    return text;
  }
  return {};
}

bool asksForHelp(const std::vector<std::string>& args) {
  return std::any_of(args.begin(), args.end(),
                     [](const std::string& a) { return a == "--help" || a == "-h"; });
}

}  // namespace stroma::cli
