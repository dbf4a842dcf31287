// SPDX-License-Identifier: MIT
// stroma-bench-mechanics: Google Benchmark of the mechanics core (bench/README.md has the
// numbers and the command). Whole scenes are stepped through the public Scene API; the
// corotational tetrahedron and the assembly are reached through the untyped interfaces a
// solver uses (BaseForceField, MechanicalOperations), never through a plugin's class.
//
// Scenes of ../shared (SOFA's examples and meshes) are found through STROMA_SHARED_DIR (the
// environment variable, else the folder beside the source tree); an entry whose files are
// absent reports a skip with the path it looked for.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/Message.h"
#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "simulation/ForceField.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Scene.h"
#include "simulation/Solvers.h"

namespace stroma::bench {
namespace {

namespace fs = std::filesystem;

fs::path sourceDir() { return STROMA_SOURCE_DIR; }

fs::path sharedDir() {
  if (const char* env = std::getenv("STROMA_SHARED_DIR"); env && *env) return env;
  return STROMA_SHARED_DIR;
}

/// A loaded scene and the Runtime it was made with (destroyed after it).
struct LoadedScene {
  std::unique_ptr<Runtime> runtime = std::make_unique<Runtime>();
  std::unique_ptr<Scene> scene = std::make_unique<Scene>(*runtime);
  ~LoadedScene() { scene.reset(); }
};

/// The errors of a scene's log, one per line.
std::string errorsOf(Scene& scene) {
  std::string text;
  for (const Message& m : scene.log().messages())
    if (m.level == MessageLevel::error) text += formatForConsole(m) + '\n';
  return text;
}

/// Set when an entry failed (a scene that did not load or step): main then returns 1, so that
/// the smoke test fails. A missing input file is a skip, not a failure.
bool g_failed = false;

void fail(benchmark::State& state, const std::string& why) {
  g_failed = true;
  state.SkipWithError(why.c_str());
}

/// Loads a file (relative names also searched in SOFA's share/ when it exists) or, when `xml`
/// is not empty, that text. Skips the benchmark with the reason and returns false when an
/// input file (`file`, or `needs` when given) is absent, or when the scene did not load.
bool load(benchmark::State& state, LoadedScene& loaded, int threads, const fs::path& file,
          const std::string& xml = {}, const fs::path& needs = {}) {
  for (const fs::path& input : {xml.empty() ? file : fs::path(), needs})
    if (!input.empty() && !fs::exists(input)) {
      state.SkipWithError(("skipped, not found: " + input.string() +
                           " (set STROMA_SHARED_DIR to the folder holding sofa/)")
                              .c_str());
      return false;
    }
  if (fs::exists(sharedDir() / "sofa" / "share"))
    loaded.runtime->addDataDirectory(sharedDir() / "sofa" / "share");
  loaded.scene->setThreadCount(threads);
  const bool ok = xml.empty() ? loaded.scene->loadFile(file) : loaded.scene->loadString(xml);
  if (!ok) {
    fail(state, "scene did not load:\n" + errorsOf(*loaded.scene));
    return false;
  }
  return true;
}

/// Depth-first: the first object of type T in the scene.
template <class T>
T* findFirst(const Node& node) {
  if (T* t = node.get<T>()) return t;
  for (const auto& child : node.children())
    if (T* t = findFirst<T>(*child)) return t;
  return nullptr;
}

template <class T>
T* objectAt(Scene& scene, const std::string& path) {
  std::string why;
  return dynamic_cast<T*>(resolveObjectPath(scene.root(), path, why));
}

// --- 1 and 4: whole scenes, steps per second ---------------------------------------------

/// Steps per run of a scene entry: STROMA_BENCH_STEPS, default 100 (the smoke test uses 2).
int stepsPerRun() {
  const char* env = std::getenv("STROMA_BENCH_STEPS");
  const int steps = env ? std::atoi(env) : 100;
  return steps > 0 ? steps : 100;
}

/// Each iteration loads `file` (untimed) and times its first stepsPerRun() steps, so that
/// every run covers the same part of the motion (CG needs fewer iterations once a body comes
/// to rest). threads: 1, or 0 for all cores. Counters: steps/s (wall) and the mean CG
/// iterations per step when the scene's linear solver reports them.
void stepScene(benchmark::State& state, const fs::path& file, int threads, const fs::path& needs) {
  const int steps = stepsPerRun();
  std::unique_ptr<LoadedScene> loaded;
  double cgIterations = 0;
  int threadCount = 0;
  for (auto _ : state) {
    state.PauseTiming();
    loaded = std::make_unique<LoadedScene>();
    // A skip or failure leaves the loop at once (Google Benchmark allows no timer call after).
    if (!load(state, *loaded, threads, file, {}, needs)) break;
    Scene& scene = *loaded->scene;
    threadCount = scene.threadCount();
    BaseData* iterations = nullptr;
    if (auto* solver = findFirst<LinearSolver>(scene.root()))
      iterations = solver->findData("lastIterations");
    state.ResumeTiming();
    bool stepped = true;
    for (int i = 0; i < steps && stepped; ++i) {
      stepped = scene.step();
      if (iterations) cgIterations += std::atof(iterations->valueText().c_str());
    }
    if (!stepped) {
      fail(state, "step failed:\n" + errorsOf(scene));
      break;
    }
    state.PauseTiming();
    loaded.reset();
    state.ResumeTiming();
  }
  const double totalSteps = static_cast<double>(steps) * static_cast<double>(state.iterations());
  state.counters["steps/s"] = benchmark::Counter(totalSteps, benchmark::Counter::kIsRate);
  state.counters["threads"] = threadCount;
  if (cgIterations > 0) state.counters["cgIterations/step"] = cgIterations / totalSteps;
}

const fs::path kSofaExamples = fs::path("sofa") / "examples";

void registerSceneBenchmarks() {
  struct Entry {
    const char* name;
    fs::path file;
    bool allThreads;
    fs::path needs;  ///< a data file the scene reads, when not beside it
  };
  const fs::path matrixAssembly = kSofaExamples / "Benchmark" / "Performance" / "MatrixAssembly";
  const std::vector<Entry> entries = {
      {"Scene/Organ", sourceDir() / "scenes/organ/Organ.scn", true, {}},
      {"Sofa/Liver", sourceDir() / "bench/scenes/Liver.scn", false,
       sharedDir() / "sofa/share/mesh/liver.msh"},
      {"Sofa/BeamBenchmark", sourceDir() / "bench/scenes/BeamBenchmark.scn", false, {}},
      {"Sofa/MatrixAssembly_matrixfreeCG",
       sharedDir() / matrixAssembly / "MatrixAssembly_matrixfreeCG.scn",
       false,
       {}},
      {"Sofa/MatrixAssembly_assembledCG",
       sharedDir() / matrixAssembly / "MatrixAssembly_assembledCG.scn",
       false,
       {}},
      {"Sofa/MatrixAssembly_direct",
       sharedDir() / matrixAssembly / "MatrixAssembly_direct.scn",
       false,
       {}},
      {"Sofa/HexahedronFEMForceField",
       sourceDir() / "bench/scenes/HexahedronFEMForceField.scn",
       false,
       {}},
  };
  for (const Entry& e : entries) {
    for (int threads : {1, 0}) {
      if (threads == 0 && !e.allThreads) continue;
      const std::string name = std::string(e.name) + (threads == 1 ? "/threads:1" : "/threads:all");
      benchmark::RegisterBenchmark(name.c_str(),
                                   [file = e.file, threads, needs = e.needs](benchmark::State& s) {
                                     stepScene(s, file, threads, needs);
                                   })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
}

// --- 2: corotational tetrahedra, per element ---------------------------------------------

/// A clamped beam of 20 x 6 x 6 cells split into 4320 tetrahedra (RegularGridTopology and
/// Hexa2TetraTopologicalMapping), bent by 20 steps under gravity so that the elements are
/// rotated and strained before the force field is timed.
std::string tetrahedronBeamXml(const std::string& method) {
  return R"(<Node name="root" dt="0.02" gravity="0 -9.81 0">
  <Node name="Beam">
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1" />
    <CGLinearSolver iterations="100" tolerance="1e-8" threshold="1e-20" />
    <RegularGridTopology name="grid" n="21 7 7" min="0 -0.05 -0.05" max="0.4 0.05 0.05" />
    <MechanicalObject name="dofs" template="Vec3" position="@grid.position" />
    <TetrahedronSetTopologyContainer name="tetrahedra" />
    <Hexa2TetraTopologicalMapping input="@grid" output="@tetrahedra" />
    <DiagonalMass name="mass" massDensity="1000" />
    <TetrahedronFEMForceField name="FEM" method=")" +
         method + R"(" youngModulus="5e4" poissonRatio="0.45" />
    <BoxROI name="clampedEnd" box="-0.001 -0.06 -0.06  0.001 0.06 0.06"
            position="@dofs.rest_position" />
    <FixedConstraint indices="@clampedEnd.indices" />
  </Node>
</Node>
)";
}

constexpr int kTetrahedronBeamElements = 20 * 6 * 6 * 6;

/// A force field of a loaded scene (at @/Beam/FEM), reached as a solver reaches it, with its
/// work vectors.
struct FieldUnderTest {
  LoadedScene loaded;
  BaseForceField* field = nullptr;
  std::unique_ptr<MechanicalOperations> mop;
  VecId f, dx, df;

  /// Loads `xml`, runs `steps` steps, then moves the positions by `deform` when given, sets dx
  /// and computes the forces once (the rotations of the current positions).
  bool setUp(benchmark::State& state, const std::string& xml, int steps,
             void (*deform)(Eigen::VectorXd& positions) = nullptr) {
    if (!load(state, loaded, 1, "<string>", xml)) return false;
    for (int i = 0; i < steps; ++i) loaded.scene->step();
    field = objectAt<BaseForceField>(*loaded.scene, "@/Beam/FEM");
    if (!field) {
      fail(state, "no force field at @/Beam/FEM");
      return false;
    }
    // The operations of the beam's solver node (the root has no solver: it sees no state).
    Node* solverNode = loaded.scene->root().findChild("Beam");
    mop = std::make_unique<MechanicalOperations>(*solverNode, loaded.scene->timing());
    f = mop->allocDeriv();
    dx = mop->allocDeriv();
    df = mop->allocDeriv();
    if (deform) {
      Eigen::VectorXd x;
      mop->gather(VecId::position(), x);
      deform(x);
      mop->scatter(x, VecId::position());
    }
    // dx: a smooth field of unit size (as a CG direction), df: cleared by the loop.
    Eigen::VectorXd values(static_cast<Eigen::Index>(mop->systemSize()));
    for (Eigen::Index i = 0; i < values.size(); ++i) values[i] = std::sin(0.37 * double(i));
    mop->scatter(values, dx);
    field->accumulateForce(MechanicalParams{}, f);  // rotations of the current positions
    return true;
  }
};

void timeAddForce(benchmark::State& state, FieldUnderTest& beam, int elements) {
  const MechanicalParams mp;
  for (auto _ : state) {
    beam.field->accumulateForce(mp, beam.f);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * elements);
  state.counters["elements"] = elements;
}

void timeAddDForce(benchmark::State& state, FieldUnderTest& beam, int elements) {
  MechanicalParams mp;
  mp.kFactor = -1e-4;
  for (auto _ : state) {
    beam.field->accumulateDForce(mp, beam.df, beam.dx);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * elements);
  state.counters["elements"] = elements;
}

/// A = M + kFactor K (EulerImplicitSolver's matrix, without damping), assembled again on the
/// pattern of the first assembly: the refill of an assembled solver each step.
void timeAssembledRefill(benchmark::State& state, FieldUnderTest& beam, double kFactor,
                         int elements) {
  MechanicalParams mp;
  mp.mFactor = 1;
  mp.kFactor = kFactor;
  AssembledMatrix A;
  beam.mop->assemble(mp, A);  // builds the pattern
  const std::uint64_t pattern = A.patternRevision();
  for (auto _ : state) {
    beam.mop->assemble(mp, A);
    benchmark::ClobberMemory();
  }
  if (A.patternRevision() != pattern) fail(state, "the pattern changed between refills");
  const auto nonzeros = static_cast<double>(A.matrix().nonZeros());
  state.counters["nonzeros"] = nonzeros;
  state.counters["nonzeros/s"] = benchmark::Counter(
      nonzeros * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["elements"] = elements;
}

void tetrahedronAddForce(benchmark::State& state, const std::string& method) {
  FieldUnderTest beam;
  if (beam.setUp(state, tetrahedronBeamXml(method), 20))
    timeAddForce(state, beam, kTetrahedronBeamElements);
}

void tetrahedronAddDForce(benchmark::State& state, const std::string& method) {
  FieldUnderTest beam;
  if (beam.setUp(state, tetrahedronBeamXml(method), 20))
    timeAddDForce(state, beam, kTetrahedronBeamElements);
}

BENCHMARK_CAPTURE(tetrahedronAddForce, large, std::string("large"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tetrahedronAddForce, polar, std::string("polar"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tetrahedronAddDForce, large, std::string("large"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tetrahedronAddDForce, polar, std::string("polar"))->Unit(benchmark::kMicrosecond);

// --- 3: assembled matrix refill ----------------------------------------------------------

/// The bent tetrahedron beam's A = M - h^2 K.
void assembledRefill(benchmark::State& state) {
  FieldUnderTest beam;
  if (beam.setUp(state, tetrahedronBeamXml("large"), 20))
    timeAssembledRefill(state, beam, -4e-4, kTetrahedronBeamElements);
}

BENCHMARK(assembledRefill)->Unit(benchmark::kMillisecond);

// --- Hexahedra of issue 5: force, product and assembly of a 32^3 grid -------------------

/// bench/scenes/MultigridBeam049.scn's beam (32^3 hexahedra, method large, nu = 0.49) with a CG
/// solver (never run), bent and twisted smoothly (hexahedronBeamTwist) so that every element
/// rotates.
const char* const kHexahedronBeamXml = R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <Node name="Beam">
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1" />
    <CGLinearSolver iterations="10" tolerance="1e-8" threshold="1e-20" />
    <RegularGridTopology name="grid" n="33 33 33" min="0 0 0" max="2 1 1" />
    <MechanicalObject name="dofs" position="@grid.position" />
    <UniformMass totalMass="1" />
    <BoxROI name="clampedEnd" box="-0.001 -1 -1  0.001 2 2" position="@dofs.rest_position" />
    <FixedProjectiveConstraint indices="@clampedEnd.indices" />
    <HexahedronFEMForceField name="FEM" method="large" youngModulus="40000" poissonRatio="0.49" />
  </Node>
</Node>
)";
constexpr int kHexahedronBeamElements = 32 * 32 * 32;

/// The beam bent down and twisted about its axis (x), 0.3 rad at the free end.
void hexahedronBeamTwist(Eigen::VectorXd& x) {
  for (Eigen::Index i = 0; i + 2 < x.size(); i += 3) {
    const double s = x[i] / 2, angle = 0.3 * s, y = x[i + 1] - 0.5, z = x[i + 2] - 0.5;
    x[i + 1] = 0.5 + std::cos(angle) * y - std::sin(angle) * z - 0.2 * s * s;
    x[i + 2] = 0.5 + std::sin(angle) * y + std::cos(angle) * z;
  }
}

void hexahedronAddForce(benchmark::State& state) {
  FieldUnderTest beam;
  if (beam.setUp(state, kHexahedronBeamXml, 0, hexahedronBeamTwist))
    timeAddForce(state, beam, kHexahedronBeamElements);
}

void hexahedronAddDForce(benchmark::State& state) {
  FieldUnderTest beam;
  if (beam.setUp(state, kHexahedronBeamXml, 0, hexahedronBeamTwist))
    timeAddDForce(state, beam, kHexahedronBeamElements);
}

/// M - h^2 K of the beam through the solver's assembly (its filter of fixed rows included).
void hexahedronAssembledRefill(benchmark::State& state) {
  FieldUnderTest beam;
  if (beam.setUp(state, kHexahedronBeamXml, 0, hexahedronBeamTwist))
    timeAssembledRefill(state, beam, -1e-4, kHexahedronBeamElements);
}

/// The force field's part of that refill: its K added straight into an AssembledMatrix (one
/// addBlocks call per element), without the solver's filter of fixed rows.
void hexahedronAddKToMatrix(benchmark::State& state) {
  FieldUnderTest beam;
  if (!beam.setUp(state, kHexahedronBeamXml, 0, hexahedronBeamTwist)) return;
  MechanicalParams mp;
  mp.kFactor = -1e-4;
  StateOffsets offsets;
  offsets.set(beam.field->states().front(), 0);
  AssembledMatrix A;
  const auto assemble = [&] {
    A.begin(beam.mop->systemSize());
    beam.field->accumulateKMatrix(mp, A, offsets);
    A.finish();
  };
  assemble();  // builds the pattern
  const std::uint64_t pattern = A.patternRevision();
  for (auto _ : state) {
    assemble();
    benchmark::ClobberMemory();
  }
  if (A.patternRevision() != pattern) fail(state, "the pattern changed between refills");
  state.SetItemsProcessed(state.iterations() * kHexahedronBeamElements);
}

BENCHMARK(hexahedronAddForce)->Unit(benchmark::kMillisecond);
BENCHMARK(hexahedronAddDForce)->Unit(benchmark::kMillisecond);
BENCHMARK(hexahedronAssembledRefill)->Unit(benchmark::kMillisecond);
BENCHMARK(hexahedronAddKToMatrix)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stroma::bench

int main(int argc, char** argv) {
  stroma::bench::registerSceneBenchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return stroma::bench::g_failed ? 1 : 0;
}
