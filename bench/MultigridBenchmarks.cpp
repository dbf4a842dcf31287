// SPDX-License-Identifier: MIT
// stroma-bench-multigrid: the multigrid solver against plain CG on the cantilever of seed 001
// table 5.2, and the issue 5 target (a near-incompressible 32^3 beam at 1e-3 error per implicit
// step). bench/README.md has the numbers and the command.
//
// Table52/<method>: one static solve K u = f of a beam of 2 x 1 x 1 m in 32^3 hexahedra
// (32768 elements, 35937 nodes; E = 40000 Pa, nu = 0.3, small-strain elements, clamped at
// x = 0, gravity 10^6 g along -y), by the linear solver named <method>, through the same call a
// solver makes (assembly and multigrid setup included). Reference: kReference below.
// Counters: error_% = 100 ||u - u_ref|| / ||u_ref||, processor (cpu_) and wall milliseconds per
// solve, note = 100 / (error_% x cpu s)
// (the note of table 5.2, one problem instead of a mean over steps).
// Table52/Summary: note(method) / note(CGfast), and the speed-up at equal error: the time plain
// CG (assembled, unpreconditioned) needs to reach the method's error, its iterations counted
// against the reference and timed as CGfast plus CGmax's time per further iteration, over the
// method's time. The times include the assembly of K (the same for every method).
// Beam049/cycles:N: the same beam with nu = 0.49, corotational elements (method large), 1 kg,
// gravity 9.81, implicit Euler (dt 0.01, Rayleigh 0.1 / 0.1), MG4 with N V-cycles per step:
// steps per processor second on one thread, and the relative error of the step's linear solve
// against the reference on the system of the state reached (A = (1 + h rm) M - h (h + rs) K, b = h
// f + h^2 K v).
//
// STROMA_BENCH_MULTIGRID_CELLS (default 32) sets the cells per axis; the ctest smoke run uses 8.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <map>
#include <memory>
#include <string>

#include "core/Message.h"
#include "core/Runtime.h"
#include "linalg/AssembledMatrix.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Scene.h"
#include "simulation/Solvers.h"
#include "simulation/Timing.h"

namespace stroma::bench {
namespace {

bool g_failed = false;

/// Processor time of this process (one thread): on a shared, loaded machine it measures the
/// work, where the wall clock also counts the waits for a core.
double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

int cellsPerAxis() {
  if (const char* env = std::getenv("STROMA_BENCH_MULTIGRID_CELLS"); env && std::atoi(env) > 1)
    return std::atoi(env);
  return 32;
}

int benchSteps() {
  if (const char* env = std::getenv("STROMA_BENCH_STEPS"); env && std::atoi(env) > 0)
    return std::atoi(env);
  return 20;
}

std::string beamScene(double nu, const std::string& method, double g, double mass,
                      const std::string& solvers) {
  const std::string n = std::to_string(cellsPerAxis() + 1);
  return "<Node name=\"root\" dt=\"0.01\" gravity=\"0 " + std::to_string(-g) +
         " 0\">\n<Node name=\"Body\">\n" + solvers + "\n<RegularGridTopology name=\"grid\" n=\"" +
         n + " " + n + " " + n +
         "\" min=\"0 0 0\" max=\"2 1 1\"/>\n"
         "<MechanicalObject name=\"dofs\" position=\"@grid.position\"/>\n"
         "<UniformMass totalMass=\"" +
         std::to_string(mass) +
         "\"/>\n"
         "<BoxROI name=\"clampedEnd\" box=\"-0.001 -1 -1  0.001 2 2\" "
         "position=\"@dofs.rest_position\"/>\n"
         "<FixedProjectiveConstraint indices=\"@clampedEnd.indices\"/>\n"
         "<HexahedronFEMForceField method=\"" +
         method +
         "\" youngModulus=\"40000\" "
         "poissonRatio=\"" +
         std::to_string(nu) + "\"/>\n</Node>\n</Node>\n";
}

/// A loaded scene and the Runtime it was made with (destroyed after it).
struct LoadedScene {
  explicit LoadedScene(const std::string& xml) {
    scene->setThreadCount(1);
    loaded = scene->loadString(xml);
    for (const Message& m : scene->log().messages())
      if (m.level == MessageLevel::error) errors += formatForConsole(m) + '\n';
    loaded = loaded && errors.empty();
  }
  ~LoadedScene() { scene.reset(); }
  Node& body() { return *scene->root().findChild("Body"); }
  LinearSolver* solver(const std::string& name) {
    return dynamic_cast<LinearSolver*>(body().findObject(name));
  }
  std::unique_ptr<Runtime> runtime = std::make_unique<Runtime>();
  std::unique_ptr<Scene> scene = std::make_unique<Scene>(*runtime);
  bool loaded = false;
  std::string errors;
};

// ---------------------------------------------------------------------------------------------
// Table 5.2

/// The reference: multigrid-preconditioned CG to a relative residual of 1e-12 (its convergence
/// to the direct solution is tested against SparseLDL in MultigridLinearSolver_test). A direct
/// factorization of the 32^3 system (108k unknowns) takes minutes with the reference BLAS of
/// this machine.
const std::string kReference =
    "<MultigridLinearSolver name=\"reference\" levels=\"4\" conjugateGradient=\"true\" "
    "iterations=\"300\" tolerance=\"1e-12\"/>\n";

const char* const kCG = R"(template="CompressedRowSparseMatrixMat3x3d" tolerance="0" )"
                        R"(threshold="1e-300" )";

std::string mgSolver(const std::string& name, int levels, const std::string& extra = "") {
  const std::string iterations =
      extra.find("iterations=") == std::string::npos ? "iterations=\"1\" " : "";
  return "<MultigridLinearSolver name=\"" + name + "\" levels=\"" + std::to_string(levels) + "\" " +
         iterations + "tolerance=\"0\" " + extra + "/>\n";
}

/// The static problem of table 5.2, loaded once, with its reference solution.
struct Table52 {
  Table52()
      : loaded(beamScene(
            0.3, "small", 1e6 * 9.81, 1.0,
            kReference + "<CGLinearSolver name=\"CGfast\" iterations=\"10\" " + kCG +
                "/>\n<CGLinearSolver name=\"CGmax\" iterations=\"150\" " + kCG + "/>\n" +
                mgSolver("MG1", 1) + mgSolver("MG2", 2) + mgSolver("MG3", 3) + mgSolver("MG4", 4) +
                mgSolver("FMG4", 4, "cycle=\"full\"") +
                mgSolver("MG4-FCG5", 4, "conjugateGradient=\"true\" iterations=\"5\"") +
                mgSolver("MG4-FCG10", 4, "conjugateGradient=\"true\" iterations=\"10\""))) {
    if (!loaded.loaded) return;
    mop = std::make_unique<MechanicalOperations>(loaded.body(), loaded.scene->timing());
    f = mop->allocDeriv();
    u = mop->allocDeriv();
    mop->computeForce(MechanicalParams{}, f);
    mop->projectResponse(f);
    mp.mFactor = 0;
    mp.kFactor = -1;  // A = -df/dx = K, as StaticSolver
    referenceReport = loaded.solver("reference")->solve(*mop, mp, u, f);
    mop->gather(u, reference);
  }
  LoadedScene loaded;
  std::unique_ptr<MechanicalOperations> mop;
  VecId f, u;
  MechanicalParams mp;
  Eigen::VectorXd reference;
  LinearSolveReport referenceReport;
  std::map<std::string, double> note, error, seconds;
};

Table52& table52() {
  static Table52 problem;
  return problem;
}

void table52Method(benchmark::State& state, const std::string& name) {
  Table52& p = table52();
  LinearSolver* solver = p.loaded.loaded ? p.loaded.solver(name) : nullptr;
  if (!solver) {
    g_failed = true;
    state.SkipWithError(("the table 5.2 scene did not load: " + p.loaded.errors).c_str());
    return;
  }
  double total = 0, wall = 0;
  long long solves = 0;
  for (auto _ : state) {
    p.mop->vOp(p.u, VecId::null(), VecId::null(), 0.0);
    const double start = cpuSeconds();
    const auto wallStart = std::chrono::steady_clock::now();
    solver->solve(*p.mop, p.mp, p.u, p.f);
    total += cpuSeconds() - start;
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    ++solves;
  }
  Eigen::VectorXd solution;
  p.mop->gather(p.u, solution);
  const double errorPercent = 100 * (solution - p.reference).norm() / p.reference.norm();
  const double secondsPerSolve = total / double(solves);
  p.error[name] = errorPercent;
  p.seconds[name] = secondsPerSolve;
  p.note[name] = 100 / (errorPercent * secondsPerSolve);
  state.counters["error_%"] = errorPercent;
  state.counters["cpu_ms/solve"] = 1e3 * secondsPerSolve;
  state.counters["wall_ms/solve"] = 1e3 * wall / double(solves);
  state.counters["note"] = p.note[name];
}

/// Iterations plain CG (assembled, unpreconditioned, from 0) needs for an error <= `target`
/// (relative, not %), at most `limit`.
int cgIterationsToReach(Table52& p, double target, int limit) {
  AssembledMatrix matrix;
  p.mop->assemble(p.mp, matrix);
  const Eigen::SparseMatrix<double>& A = matrix.matrix();
  Eigen::VectorXd b;
  p.mop->gather(p.f, b);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size()), r = b, d = r, q;
  double rho = r.squaredNorm();
  const double referenceNorm = p.reference.norm();
  for (int k = 1; k <= limit; ++k) {
    q.noalias() = A * d;
    const double alpha = rho / d.dot(q);
    x += alpha * d;
    r -= alpha * q;
    if ((x - p.reference).norm() <= target * referenceNorm) return k;
    const double next = r.squaredNorm();
    d = r + (next / rho) * d;
    rho = next;
  }
  return limit + 1;
}

void table52Summary(benchmark::State& state) {
  Table52& p = table52();
  for (auto _ : state) benchmark::DoNotOptimize(p.note.size());
  if (!p.note.count("MG4") || !p.note.count("CGfast") || !p.note.count("CGmax")) {
    state.SkipWithError("run with the Table52 entries of MG4, CGfast and CGmax");
    return;
  }
  state.counters["reference_residual"] = p.referenceReport.residual;
  state.counters["reference_cycles"] = p.referenceReport.iterations;
  state.counters["note_MG4/CGfast"] = p.note["MG4"] / p.note["CGfast"];
  // CG's time for n iterations: CGfast's (assembly and 10 iterations) plus CGmax's time per
  // further iteration.
  const auto cgSeconds = [&](int n) {
    return p.seconds["CGfast"] + (n - 10) * (p.seconds["CGmax"] - p.seconds["CGfast"]) / 140;
  };
  const int limit = 20000;
  for (const char* name : {"MG1", "MG4", "FMG4", "MG4-FCG5"}) {
    if (!p.error.count(name)) continue;
    const int iterations = cgIterationsToReach(p, p.error[name] / 100, limit);
    state.counters[std::string("CG_its_to_") + name + "_error"] = iterations;
    state.counters[std::string("speedup_at_") + name + "_error"] =
        cgSeconds(iterations) / p.seconds[name];
  }
  for (const char* name : {"MG1", "FMG4", "MG4-FCG5"})
    if (p.note.count(name))
      state.counters[std::string("note_") + name + "/CGfast"] = p.note[name] / p.note["CGfast"];
}

// ---------------------------------------------------------------------------------------------
// The issue's target: nu = 0.49, implicit Euler, MG4 with N cycles per step.

void beam049(benchmark::State& state) {
  const int cycles = int(state.range(0));
  const std::string accelerated = state.range(1) ? "conjugateGradient=\"true\"" : "";
  LoadedScene s(
      beamScene(0.49, "large", 9.81, 1.0,
                "<EulerImplicitSolver rayleighStiffness=\"0.1\" rayleighMass=\"0.1\"/>\n" +
                    mgSolver("mg", 4, accelerated) + kReference));
  if (!s.loaded) {
    g_failed = true;
    state.SkipWithError(("the nu = 0.49 beam did not load: " + s.errors).c_str());
    return;
  }
  std::string why;
  s.body().findObject("mg")->findData("iterations")->read(std::to_string(cycles), why);
  const int steps = benchSteps();
  long long total = 0;
  const double start = cpuSeconds();
  for (auto _ : state) {
    for (int n = 0; n < steps; ++n)
      if (!s.scene->step()) {
        g_failed = true;
        state.SkipWithError("a step failed");
        return;
      }
    total += steps;
  }
  state.counters["cpu_steps/s"] = double(total) / (cpuSeconds() - start);
  // Where a step goes (wall clock, per step): the scene's phases.
  for (const Timing::Phase& phase : s.scene->timing().phases())
    if (phase.name == "linearSolve" || phase.name == "multigridSetup" || phase.name == "assemble")
      state.counters[phase.name + "_ms/step"] = 1e3 * phase.seconds / double(total);

  // The error of MG on the next step's system, against the reference.
  MechanicalOperations mop(s.body(), s.scene->timing());
  const double h = 0.01, rm = 0.1, rs = 0.1;
  const VecId f = mop.allocDeriv(), kv = mop.allocDeriv(), b = mop.allocDeriv(),
              x = mop.allocDeriv();
  mop.computeForce(MechanicalParams{}, f);
  MechanicalParams stiffness;
  stiffness.mFactor = 0;
  stiffness.kFactor = 1;
  mop.computeMBKdx(stiffness, kv, VecId::velocity());
  mop.vOp(b, VecId::null(), f, h);
  mop.vOp(b, b, kv, h * h);
  mop.projectResponse(b);
  MechanicalParams mp;
  mp.mFactor = 1 + h * rm;
  mp.kFactor = -h * (h + rs);
  Eigen::VectorXd reference, solution;
  const LinearSolveReport referenceReport = s.solver("reference")->solve(mop, mp, x, b);
  state.counters["reference_residual"] = referenceReport.residual;
  mop.gather(x, reference);
  mop.vOp(x, VecId::null(), VecId::null(), 0.0);
  s.solver("mg")->solve(mop, mp, x, b);
  mop.gather(x, solution);
  state.counters["error"] = (solution - reference).norm() / reference.norm();
}

void registerAll() {
  for (const char* name :
       {"CGfast", "CGmax", "MG1", "MG2", "MG3", "MG4", "FMG4", "MG4-FCG5", "MG4-FCG10"})
    benchmark::RegisterBenchmark((std::string("Table52/") + name).c_str(),
                                 [name](benchmark::State& state) { table52Method(state, name); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(3);
  benchmark::RegisterBenchmark("Table52/Summary", table52Summary)->Iterations(1);
  benchmark::RegisterBenchmark("Beam049", beam049)
      ->ArgNames({"cycles", "fcg"})
      ->ArgsProduct({{1, 2, 4, 8}, {0}})
      ->ArgsProduct({{1, 2, 4, 5, 6, 8}, {1}})
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1);
}

}  // namespace
}  // namespace stroma::bench

int main(int argc, char** argv) {
  stroma::bench::registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return stroma::bench::g_failed ? 1 : 0;
}
