// SPDX-License-Identifier: MIT
// Collision detection and contact (plugins/Collision): the cost of a collision step on a
// 10,000-triangle organ-sized surface against a 1,000-triangle instrument and for its
// self-collision, and whole scenes with contact (SOFA's Demos/liver.scn and
// Demos/fallingBeamLagrangianCollision.scn unmodified, the bundled scenes/collision).
// README.md ("Collision") has the numbers and the commands. Timings are never pass/fail: the
// ctest entry only checks that every entry runs.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <random>
#include <sstream>

#include "collision/CollisionPipeline.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::bench {
namespace {

namespace fs = std::filesystem;

fs::path sharedDir() {
  if (const char* env = std::getenv("STROMA_SHARED_DIR"); env && *env) return env;
  return STROMA_SHARED_DIR;
}

int stepsPerRun() {
  const char* env = std::getenv("STROMA_BENCH_STEPS");
  const int steps = env ? std::atoi(env) : 100;
  return steps > 0 ? steps : 100;
}

bool g_failed = false;

std::string errorsOf(Scene& scene) {
  std::string text;
  for (const Message& m : scene.log().messages())
    if (m.level == MessageLevel::error) text += formatForConsole(m) + '\n';
  return text;
}

/// A closed latitude-longitude sphere of `rings` x `segments` (2 segments (rings - 1)
/// triangles), radius r, centred at c, its points moved radially by up to `bump` (seeded): the
/// mesh attributes of a MeshTopology.
std::string sphereMesh(int rings, int segments, double r, const Vec3d& c, double bump,
                       unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-bump, bump);
  std::ostringstream points, triangles;
  points.precision(10);
  auto point = [&](double polar, double azimuth) {
    const double radius = r + u(random);
    points << c.x() + radius * std::sin(polar) * std::cos(azimuth) << ' '
           << c.y() + radius * std::cos(polar) << ' '
           << c.z() + radius * std::sin(polar) * std::sin(azimuth) << "  ";
  };
  point(0, 0);  // north pole: 0
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) point(M_PI * i / rings, 2 * M_PI * j / segments);
  point(M_PI, 0);  // south pole
  const int south = 1 + (rings - 1) * segments;
  auto at = [&](int ring, int j) { return 1 + (ring - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) {
    triangles << 0 << ' ' << at(1, j + 1) << ' ' << at(1, j) << "  ";
    triangles << south << ' ' << at(rings - 1, j) << ' ' << at(rings - 1, j + 1) << "  ";
  }
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      triangles << at(i, j) << ' ' << at(i, j + 1) << ' ' << at(i + 1, j) << "  ";
      triangles << at(i, j + 1) << ' ' << at(i + 1, j + 1) << ' ' << at(i + 1, j) << "  ";
    }
  return "position=\"" + points.str() + "\" triangles=\"" + triangles.str() + "\"";
}

std::string surface(const std::string& name, const std::string& mesh, const std::string& extra) {
  return "<Node name=\"" + name + "\"><MeshTopology name=\"mesh\" " + mesh +
         "/><MechanicalObject name=\"dofs\" position=\"@mesh.position\"/>"
         "<PointCollisionModel " + extra + "/><LineCollisionModel " + extra +
         "/><TriangleCollisionModel " + extra + "/></Node>";
}

/// Times computeCollisions on a scene whose surfaces deform a little at every step (every
/// point moved by up to `jitter` from its rest, so that the trees are refitted and the
/// contacts change). Counters: contacts per step, collision steps/s.
void collisionSteps(benchmark::State& state, const std::string& xml, double jitter) {
  Runtime runtime;
  Scene scene(runtime);
  if (!scene.loadString(xml)) {
    g_failed = true;
    state.SkipWithError(("scene did not load:\n" + errorsOf(scene)).c_str());
    return;
  }
  auto* phase = scene.root().get<CollisionPhase>();
  std::vector<MechanicalState<Vec3Types>*> states;
  std::vector<std::vector<Vec3d>> rest;
  for (const auto& child : scene.root().children()) {
    states.push_back(child->get<MechanicalState<Vec3Types>>());
    rest.push_back(states.back()->readCoord(VecId::position()));
  }
  // Precomputed deformations, so that the timed loop only runs the collision step.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<std::vector<std::vector<Vec3d>>> frames(8, rest);
  for (auto& frame : frames)
    for (auto& points : frame)
      for (Vec3d& x : points) x += Vec3d(u(random), u(random), u(random));
  std::size_t n = 0;
  double contacts = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const auto& frame = frames[n++ % frames.size()];
    for (std::size_t k = 0; k < states.size(); ++k)
      states[k]->writeCoord(VecId::position()) = frame[k];
    state.ResumeTiming();
    phase->computeCollisions(scene.root(), scene.timing());
    state.PauseTiming();
    for (const ModelPairContacts& pair : phase->lastContacts()) contacts += pair.contacts.size();
    state.ResumeTiming();
  }
  state.counters["contacts/step"] = contacts / static_cast<double>(std::max<std::size_t>(n, 1));
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsRate);
}

const std::string kPipeline =
    "<CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>"
    "<MinProximityIntersection alarmDistance=\"0.002\" contactDistance=\"0.001\"/>"
    "<CollisionResponse/>";

// An organ-sized surface (a bumpy sphere of radius 10 cm, 10,000 triangles, 5,002 points) and
// an instrument (a sphere of radius 2 cm, 1,000 triangles) sunk halfway through its surface.
void OrganVsInstrument(benchmark::State& state) {
  const std::string xml = "<Node name=\"root\" dt=\"0.01\" gravity=\"0 0 0\">" + kPipeline +
                          surface("Organ", sphereMesh(51, 100, 0.1, Vec3d::Zero(), 0.002, 1), "") +
                          surface("Instrument",
                                  sphereMesh(21, 25, 0.02, Vec3d(0.1, 0, 0), 0.0, 2), "") +
                          "</Node>";
  collisionSteps(state, xml, 0.0005);
}
BENCHMARK(OrganVsInstrument)->Unit(benchmark::kMicrosecond);

// The same organ surface against itself (selfCollision): every pair of primitives of the
// surface whose boxes overlap is tested; neighbours sharing a vertex are skipped.
void OrganSelfCollision(benchmark::State& state) {
  const std::string xml =
      "<Node name=\"root\" dt=\"0.01\" gravity=\"0 0 0\">" + kPipeline +
      surface("Organ", sphereMesh(51, 100, 0.1, Vec3d::Zero(), 0.002, 1), "selfCollision=\"1\"") +
      "</Node>";
  collisionSteps(state, xml, 0.0005);
}
BENCHMARK(OrganSelfCollision)->Unit(benchmark::kMicrosecond);

/// Steps/s of a scene file: each iteration loads it (untimed) and times stepsPerRun() steps.
/// With `phase`, also that phase's share of the steps' time (counter "<phase> share", %).
void sceneSteps(benchmark::State& state, const fs::path& file, const char* phase = nullptr) {
  if (!fs::exists(file)) {
    state.SkipWithError(("skipped, not found: " + file.string() +
                         " (set STROMA_SHARED_DIR to the folder holding sofa/)")
                            .c_str());
    return;
  }
  const int steps = stepsPerRun();
  double phaseSeconds = 0, stepSeconds = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto runtime = std::make_unique<Runtime>();
    runtime->addDataDirectory(sharedDir() / "sofa" / "share");
    runtime->addDataDirectory(sharedDir() / "sofa" / "examples");
    auto scene = std::make_unique<Scene>(*runtime);
    scene->setThreadCount(1);
    if (!scene->loadFile(file)) {
      g_failed = true;
      state.SkipWithError(("scene did not load:\n" + errorsOf(*scene)).c_str());
      break;
    }
    state.ResumeTiming();
    bool stepped = true;
    for (int i = 0; i < steps && stepped; ++i) stepped = scene->step();
    state.PauseTiming();
    if (!stepped) {
      g_failed = true;
      state.SkipWithError(("step failed:\n" + errorsOf(*scene)).c_str());
      break;
    }
    if (phase) {
      phaseSeconds += scene->timing().seconds(phase);
      stepSeconds += scene->timing().seconds("step");
    }
    scene.reset();
    runtime.reset();
    state.ResumeTiming();
  }
  state.counters["steps/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * steps, benchmark::Counter::kIsRate);
  if (phase && stepSeconds > 0)
    state.counters[std::string(phase) + " share %"] = 100 * phaseSeconds / stepSeconds;
}

void SofaLiver(benchmark::State& state) {
  sceneSteps(state, sharedDir() / "sofa/examples/Demos/liver.scn");
}
BENCHMARK(SofaLiver)->Unit(benchmark::kMillisecond);

// SOFA's Lagrangian contact demo unmodified: a FEM beam (625 nodes, PCGLinearSolver
// preconditioned by SparseLDLSolver) falls 1 m onto a box and rests on it with friction
// (FrictionContactConstraint, GenericConstraintSolver, LinearSolverConstraintCorrection); the
// constraint phase's share of the step beside the rate.
void SofaFallingBeam(benchmark::State& state) {
  sceneSteps(state, sharedDir() / "sofa/examples/Demos/fallingBeamLagrangianCollision.scn",
             "constraints");
}
BENCHMARK(SofaFallingBeam)->Unit(benchmark::kMillisecond);

void OrganOnFloor(benchmark::State& state) {
  sceneSteps(state, fs::path(STROMA_SOURCE_DIR) / "scenes/collision/OrganOnFloor.scn");
}
BENCHMARK(OrganOnFloor)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stroma::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return stroma::bench::g_failed ? 1 : 0;
}
