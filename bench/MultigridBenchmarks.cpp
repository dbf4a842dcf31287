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
// Table52Assembled/<method>: the same problem, every method from one assembled K (the assembly
// left out), the multigrid through the kernels of plugins/Multigrid, its setup (P^T and
// Galerkin products) timed apart: error_%, cpu_ms (least of 5 runs), CG150/this (the speed-up
// over 150 CG iterations), CG150/(this+update) and CG150/(this+setup) (the numeric Galerkin
// update or the whole setup counted). Table52Assembled/Chart: error against time, as CSV and
// PNG (framework/report/Chart.h) in $STROMA_BENCH_CHART_DIR (nothing written when unset).
// Beam049/<setting>: the same beam with nu = 0.49, corotational elements (method large), 1 kg,
// gravity 9.81, implicit Euler (dt 0.01, Rayleigh 0.1 / 0.1), the multigrid settings of
// kBeam049Settings: steps per processor second on one thread after the first step (timed
// apart: first_step_cpu_s; STROMA_BENCH_STEPS steps, default 20), and the relative error of
// the next step's linear solve against the reference on the system of the state reached
// (A = (1 + h rm) M - h (h + rs) K, b = h f + h^2 K v), solved as the next step would solve
// it, every 10 steps and at the end: error (the last), error_max (the largest).
// Table52Assembled/Product-<storage>: one product with the fine K in each storage, and the
// accuracy of the block copies of every level.
//
// STROMA_BENCH_MULTIGRID_CELLS (default 32) sets the cells per axis; the ctest smoke run uses 8.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "GridTransfer.h"
#include "MultigridCycle.h"
#include "SparseGrid.h"
#include "core/Message.h"
#include "core/Runtime.h"
#include "linalg/AssembledMatrix.h"
#include "report/Chart.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Scene.h"
#include "simulation/Solvers.h"
#include "simulation/Timing.h"
#include "topology/Topology.h"

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
// Table 5.2 from one assembled operator: every method solves K u = f from u = 0 on the same
// assembled K (the assembly is left out of every time), the multigrid with the kernels of
// plugins/Multigrid (the solver's own code), its setup (P^T and the Galerkin products) timed
// apart. Times are the least processor time of 5 runs (the machine is shared).

struct KernelTable52 {
  KernelTable52() {
    Table52& p = table52();
    if (!p.loaded.loaded) return;
    AssembledMatrix assembled;
    p.mop->assemble(p.mp, assembled);
    A = assembled.matrix();
    p.mop->gather(p.f, b);
    const Topology* topology = p.loaded.body().get<Topology>();
    sparsegrid::SparseGrid fine;
    std::string error;
    if (!topology || !multigrid::makeLatticeGrid(topology->positions(), topology->hexahedra(),
                                                 nullptr, fine, error))
      return;
    std::vector<char> fixed;
    p.mop->fixedGlobalRows(fixed);
    std::vector<std::array<Index, 8>> children;
    for (int l = 0; l < 4; ++l) {
      sparsegrid::SparseGrid coarse = sparsegrid::coarsenSparseGrid(fine, &children);
      P.push_back(multigrid::expandProlongation(multigrid::makeProlongation(fine, coarse, children),
                                                3, l == 0 ? fixed : std::vector<char>{}));
      fine = std::move(coarse);
    }
    // Setup with a new pattern (P^T, Galerkin products), then a numeric update alone (what a
    // solve with coarseUpdateInterval = 1 redoes at every step).
    double start = cpuSeconds();
    cycle.setOperators(A, P, multigrid::OperatorUpdate{});
    setupSeconds = cpuSeconds() - start;
    start = cpuSeconds();
    cycle.setOperators(A, P, {.patternChanged = false, .fineSamePattern = true});
    updateSeconds = cpuSeconds() - start;
    singleCycle.setOperators(A, P, {.precision = multigrid::SymmetricBlockMatrix::Precision::single});
    ready = true;
  }
  bool ready = false;
  multigrid::SparseMatrix A;
  Eigen::VectorXd b;
  std::vector<multigrid::SparseMatrix> P;
  multigrid::MultigridCycle cycle, singleCycle;  ///< level matrices in double, in single
  double setupSeconds = 0, updateSeconds = 0;
  std::map<std::string, double> error, seconds;
};

KernelTable52& kernelTable52() {
  static KernelTable52 problem;
  return problem;
}

/// A method of the kernel comparison: solves A x = b from x = 0.
struct KernelMethod {
  const char* name;
  int cgIterations;  ///< > 0: plain CG with this many iterations
  int cycles;        ///< multigrid: cycles (the first of `kind`, then V-cycles), or, with fcg,
                     ///< flexible-CG iterations preconditioned by a cycle of `kind`
  multigrid::CycleKind kind;
  bool fcg;
  multigrid::CycleSettings settings;
  /// Plain CG: multiply with the 3 x 3 block copy of K (SymmetricBlockMatrix.h) instead of Eigen's
  /// storage; multigrid: cycles on level matrices stored in single precision.
  bool single = false, blocks = false;
};

constexpr multigrid::CycleKind kV = multigrid::CycleKind::V, kFull = multigrid::CycleKind::full,
                               kCascadic = multigrid::CycleKind::cascadic;
const KernelMethod kKernelMethods[] = {
    {"CG10", 10, 0, kV, false, {}},
    {"CG150", 150, 0, kV, false, {}},
    {"CG150-blocks", 150, 0, kV, false, {}, false, true},
    {"CG150-blocks-single", 150, 0, kV, false, {}, true, true},
    {"MG4-V(7)", 0, 1, kV, false, {7, 150, false, true}},
    {"FMG4(7)", 0, 1, kFull, false, {7, 150, false, true}},
    {"FMG4(2)-LDL", 0, 1, kFull, false, {2, 150, true, true}},
    {"FMG4(1)-LDL", 0, 1, kFull, false, {1, 150, true, true}},
    {"FCG1-V(2)-LDL", 0, 1, kV, true, {2, 150, true, true}},
    {"FCG2-V(1)-LDL", 0, 2, kV, true, {1, 150, true, true}},
    {"FCG2-V(2)-LDL", 0, 2, kV, true, {2, 150, true, true}},
    // Level matrices in single precision (3 x 3 blocks; SymmetricBlockMatrix.h).
    {"FMG4(1)-LDL-single", 0, 1, kFull, false, {1, 150, true, true}, true},
    // Per-level counts: no smoothing on the fine level (its V-cycle is the coarse correction
    // alone), 2 on the coarser ones.
    {"FMG4(0,2)-LDL-single", 0, 1, kFull, false, {1, 150, true, true, {0, 2}}, true},
    // The fine level only receives the prolongation of the 16^3 level's full cycle
    // (levelCycles 0 1): its error is that of the 16^3 solve plus the 16^3 discretization's
    // (C4(0,300): the 16^3 level nearly solved, 0.49 %).
    {"FMG4c(0,1)(0,2)-LDL-single", 0, 1, kFull, false, {1, 150, true, true, {0, 2}, {0, 1}}, true},
    {"FMG4c(0,1)(0,3)-LDL-single", 0, 1, kFull, false, {1, 150, true, true, {0, 3}, {0, 1}}, true},
    {"FMG4c(0,1)(0,3,2)-LDL-single", 0, 1, kFull, false,
     {1, 150, true, true, {0, 3, 2}, {0, 1}}, true},
    {"FMG4c(0,1)(0,2,4)-LDL-single", 0, 1, kFull, false,
     {1, 150, true, true, {0, 2, 4}, {0, 1}}, true},
    {"FMG4c(0,1)(0,3)-LDL-nopost-single", 0, 1, kFull, false,
     {1, 150, true, false, {0, 3}, {0, 1}}, true},
    {"FMG4c(0,1)(0,4)-LDL-nopost-single", 0, 1, kFull, false,
     {1, 150, true, false, {0, 4}, {0, 1}}, true},
    {"FMG4c(0,2)(0,2)-LDL-single", 0, 1, kFull, false, {1, 150, true, true, {0, 2}, {0, 2}}, true},
    // Cascadic cycles: CG on each level from the prolongation, no coarse correction going back.
    {"C4(0,300)-LDL", 0, 1, kCascadic, false, {0, 150, true, true, {0, 300}}},
    {"C4(4,16)-LDL-single", 0, 1, kCascadic, false, {0, 150, true, true, {4, 16}}, true},
};

void kernelTable52Method(benchmark::State& state, const KernelMethod& method) {
  KernelTable52& k = kernelTable52();
  if (!k.ready) {
    g_failed = true;
    state.SkipWithError("the table 5.2 scene or its grid did not load");
    return;
  }
  Eigen::VectorXd x, r, d, q;
  double best = 1e300;
  for (auto _ : state) {
    x.setZero(k.b.size());
    const double start = cpuSeconds();
    multigrid::MultigridCycle& cycle = method.single ? k.singleCycle : k.cycle;
    if (method.cgIterations > 0 && method.blocks) {
      multigrid::MultigridCycle::conjugateGradient(cycle.blocks(0), k.b, x, method.cgIterations,
                                                   0.0, r, d, q);
    } else if (method.cgIterations > 0) {
      multigrid::MultigridCycle::conjugateGradient(k.A, k.b, x, method.cgIterations, 0.0, r, d, q);
    } else if (method.fcg) {
      double residual = 0;
      cycle.flexibleConjugateGradient(k.A, k.b, x, method.cycles, 0.0, method.kind,
                                      method.settings, residual);
    } else {
      cycle.cycleFromZero(method.kind, k.b, x, method.settings);
      for (int c = 1; c < method.cycles; ++c) cycle.vCycle(0, x, k.b, method.settings);
    }
    best = std::min(best, cpuSeconds() - start);
  }
  const Eigen::VectorXd& reference = table52().reference;
  const double errorPercent = 100 * (x - reference).norm() / reference.norm();
  k.error[method.name] = errorPercent;
  k.seconds[method.name] = best;
  state.counters["error_%"] = errorPercent;
  state.counters["cpu_ms"] = 1e3 * best;
  if (k.seconds.count("CG150")) {
    state.counters["CG150/this"] = k.seconds["CG150"] / best;
    state.counters["CG150/(this+update)"] = k.seconds["CG150"] / (best + k.updateSeconds);
    state.counters["CG150/(this+setup)"] = k.seconds["CG150"] / (best + k.setupSeconds);
  }
  if (method.cgIterations == 0) {
    state.counters["setup_cpu_ms"] = 1e3 * k.setupSeconds;
    state.counters["update_cpu_ms"] = 1e3 * k.updateSeconds;
  }
}

/// Table52Assembled/Product-<storage>: one product with the fine K, least processor time of 20:
/// Eigen's compressed columns, the 3 x 3 block copy in double and in single precision.
void kernelTable52Product(benchmark::State& state, int storage) {
  KernelTable52& k = kernelTable52();
  if (!k.ready) {
    state.SkipWithError("the table 5.2 scene or its grid did not load");
    return;
  }
  Eigen::VectorXd y;
  double best = 1e300;
  for (auto _ : state) {
    const double start = cpuSeconds();
    if (storage == 0)
      multigrid::multiply(k.A, k.b, y);
    else
      multigrid::multiply((storage == 1 ? k.cycle : k.singleCycle).blocks(0), k.b, y);
    best = std::min(best, cpuSeconds() - start);
    benchmark::DoNotOptimize(y.data());
  }
  state.counters["cpu_ms"] = 1e3 * best;
  const Eigen::VectorXd exact = k.A * k.b;
  state.counters["relative_difference"] = (y - exact).norm() / exact.norm();
  if (storage > 0) {
    multigrid::MultigridCycle& cycle = storage == 1 ? k.cycle : k.singleCycle;
    for (int l = 1; l < cycle.levels(); ++l) {
      const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(cycle.matrix(l).rows(), -1.0, 1.0);
      const Eigen::VectorXd reference = cycle.matrix(l) * x;
      Eigen::VectorXd product;
      multigrid::multiply(cycle.blocks(l), x, product);
      state.counters["level" + std::to_string(l) + "_difference"] =
          (product - reference).norm() / reference.norm();
      const multigrid::SparseMatrix asymmetry =
          multigrid::SparseMatrix(cycle.matrix(l).transpose()) - cycle.matrix(l);
      state.counters["level" + std::to_string(l) + "_asymmetry"] =
          asymmetry.norm() / cycle.matrix(l).norm();
    }
  }
  state.counters["MB_read"] =
      1e-6 * double(storage == 0 ? 12 * k.A.nonZeros()
                                 : (storage == 1 ? 76 : 40) * k.cycle.blocks(0).blockCount());
}

/// Table52Assembled/Chart: relative error against processor time, plain CG after 10 to 300
/// iterations and each multigrid method of the entries run before it (their setup apart), as
/// CSV and PNG (framework/report/Chart.h) in $STROMA_BENCH_CHART_DIR (nothing when unset).
void kernelTable52Chart(benchmark::State& state) {
  KernelTable52& k = kernelTable52();
  for (auto _ : state) benchmark::DoNotOptimize(k.error.size());
  if (!k.ready) {
    state.SkipWithError("the table 5.2 scene or its grid did not load");
    return;
  }
  const Eigen::VectorXd& reference = table52().reference;
  std::vector<report::ChartSeries> series(1);
  series[0].name = "plain CG (10 to 300 iterations)";
  Eigen::VectorXd x, r, d, q;
  for (int iterations : {10, 25, 50, 100, 150, 200, 300}) {
    x.setZero(k.b.size());
    const double start = cpuSeconds();
    multigrid::MultigridCycle::conjugateGradient(k.A, k.b, x, iterations, 0.0, r, d, q);
    series[0].x.push_back(1e3 * (cpuSeconds() - start));
    series[0].y.push_back(100 * (x - reference).norm() / reference.norm());
  }
  for (const auto& [name, error] : k.error) {
    if (name.rfind("CG", 0) == 0) continue;
    series.push_back({name, {1e3 * k.seconds[name]}, {error}});
  }
  // Written only when asked for: the ctest smoke run works in the source tree.
  const char* env = std::getenv("STROMA_BENCH_CHART_DIR");
  if (!env || !*env) return;
  const std::string folder = env;
  std::error_code ignored;
  std::filesystem::create_directories(folder, ignored);
  const std::string base = folder + "/multigrid-table52";
  const report::ChartAxes axes{"Seed 001 table 5.2 problem, 32^3 hexahedra, one assembled K",
                               "processor time of the solve (ms)", "relative error (%)", true,
                               true};
  std::string problem = report::writeChartCsv(base + ".csv", axes, series);
  if (problem.empty()) problem = report::writeChartPng(base + ".png", axes, series);
  if (!problem.empty()) state.SkipWithError(problem.c_str());
}

// ---------------------------------------------------------------------------------------------
// The issue's target: nu = 0.49, implicit Euler, several multigrid settings.

/// The solver settings of the Beam049 entries (attributes of the MultigridLinearSolver "mg").
struct Beam049Setting {
  const char* name;
  const char* attributes;
};
const Beam049Setting kBeam049Settings[] = {
    // The thesis's cycle (4 coarse levels, 7 smoothing iterations per level, 150 at the
    // coarsest) in 5 iterations of flexible CG, every operator rebuilt at every step (the
    // setting measured before the second pass of bench/README.md).
    {"FCG5", "conjugateGradient=\"true\" iterations=\"5\""},
    // The same, coarse operators computed once (kept while the pattern holds).
    {"FCG5-stale", "conjugateGradient=\"true\" iterations=\"5\" coarseUpdateInterval=\"0\""},
    {"FCG4-stale", "conjugateGradient=\"true\" iterations=\"4\" coarseUpdateInterval=\"0\""},
    // ... and each step starts from the previous step's solution.
    {"FCG5-stale-warm",
     "conjugateGradient=\"true\" iterations=\"5\" coarseUpdateInterval=\"0\" "
     "warmStart=\"true\""},
    // Cheaper smoothing on the same levels: the smoother does most of the work at nu = 0.49.
    {"FCG6-s2-stale-warm",
     "conjugateGradient=\"true\" iterations=\"6\" smoothingIterations=\"2\" "
     "coarseUpdateInterval=\"0\" warmStart=\"true\""},
    // Fewer coarse levels, the coarsest solved by LDL^T (factorized once per update): coarse
    // corrections that do not lock as much as 4 levels of trilinear hexahedra.
    {"FCG4-L1direct-stale",
     "conjugateGradient=\"true\" iterations=\"4\" levels=\"1\" directCoarseSolve=\"true\" "
     "coarseUpdateInterval=\"0\""},
    {"FCG2-L1direct-s4-stale",
     "conjugateGradient=\"true\" iterations=\"2\" levels=\"1\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"4\" coarseUpdateInterval=\"0\""},
    {"FCG4-L2direct-stale",
     "conjugateGradient=\"true\" iterations=\"4\" levels=\"2\" directCoarseSolve=\"true\" "
     "coarseUpdateInterval=\"0\""},
    {"FCG3-L2direct-stale",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "coarseUpdateInterval=\"0\""},
    {"FCG4-L2direct-s3-stale",
     "conjugateGradient=\"true\" iterations=\"4\" levels=\"2\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"3\" coarseUpdateInterval=\"0\""},
    // bench/scenes/MultigridBeam049.scn of the second pass:
    {"FCG3-L2direct-s4-stale",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"4\" coarseUpdateInterval=\"0\""},
    {"FCG3-L2direct-s3-stale",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"3\" coarseUpdateInterval=\"0\""},
    // That setting with the level matrices in single precision (3 x 3 blocks).
    {"FCG3-L2direct-s4-stale-single",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"4\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\""},
    // ... and the system assembled every 4th solve, or only at the first (fineUpdateInterval:
    // the outer CG multiplies through the force field in between).
    {"FCG3-L2direct-s4-stale-single-fine4",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"4\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"4\""},
    {"FCG3-L2direct-s4-stale-single-fine0",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"4\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"0\""},
    {"FCG3-L2direct-s(4,8)-stale-single-fine4",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "levelSmoothing=\"4 8\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"4\""},
    // ... the coarse operators recomputed at every 8th assembly (every 32 steps).
    {"FCG3-L2direct-s(4,8)-coarse8-single-fine4",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "levelSmoothing=\"4 8\" coarseUpdateInterval=\"8\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"4\""},
    {"FCG4-L2direct-s(4,8)-nopost-stale-single-fine4",
     "conjugateGradient=\"true\" iterations=\"4\" levels=\"2\" directCoarseSolve=\"true\" "
     "levelSmoothing=\"4 8\" postSmoothing=\"false\" coarseUpdateInterval=\"0\" "
     "matrixPrecision=\"single\" fineUpdateInterval=\"4\""},
    {"FCG5-L2direct-s(3,8)-nopost-stale-single-fine4",
     "conjugateGradient=\"true\" iterations=\"5\" levels=\"2\" directCoarseSolve=\"true\" "
     "levelSmoothing=\"3 8\" postSmoothing=\"false\" coarseUpdateInterval=\"0\" "
     "matrixPrecision=\"single\" fineUpdateInterval=\"4\""},
    {"FCG3-L2direct-s(3,8)-stale-single-fine4",
     "conjugateGradient=\"true\" iterations=\"3\" levels=\"2\" directCoarseSolve=\"true\" "
     "levelSmoothing=\"3 8\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"4\""},
    {"FCG4-L2direct-s3-stale-single-fine4",
     "conjugateGradient=\"true\" iterations=\"4\" levels=\"2\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"3\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"4\""},
    // bench/scenes/MultigridBeam049.scn (third pass):
    {"FCG4-L2direct-s3-stale-single-fine8",
     "conjugateGradient=\"true\" iterations=\"4\" levels=\"2\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"3\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"8\""},
    {"FCG4-L2direct-s(3,2)-stale-single-fine8",
     "conjugateGradient=\"true\" iterations=\"4\" levels=\"2\" directCoarseSolve=\"true\" "
     "levelSmoothing=\"3 2\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"8\""},
    {"FCG2-L1direct-s4-stale-single-fine4",
     "conjugateGradient=\"true\" iterations=\"2\" levels=\"1\" directCoarseSolve=\"true\" "
     "smoothingIterations=\"4\" coarseUpdateInterval=\"0\" matrixPrecision=\"single\" "
     "fineUpdateInterval=\"4\""},
};

/// The relative error of the MG solver "mg" on the system the next step of `s` will solve,
/// against the reference solver: solved as the next step would solve it (stale operators and
/// warm start kept). The solve counts as one of mg's solves (its fineUpdateInterval and
/// coarseUpdateInterval counters move by one).
double nextSolveError(LoadedScene& s, double& referenceResidual) {
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
  referenceResidual = s.solver("reference")->solve(mop, mp, x, b).residual;
  mop.gather(x, reference);
  mop.vOp(x, VecId::null(), VecId::null(), 0.0);
  s.solver("mg")->solve(mop, mp, x, b);
  mop.gather(x, solution);
  return (solution - reference).norm() / reference.norm();
}

void beam049(benchmark::State& state, const Beam049Setting& setting) {
  LoadedScene s(beamScene(0.49, "large", 9.81, 1.0,
                          "<EulerImplicitSolver rayleighStiffness=\"0.1\" rayleighMass=\"0.1\"/>\n"
                          "<MultigridLinearSolver name=\"mg\" tolerance=\"0\" " +
                              std::string(setting.attributes) + "/>\n" + kReference));
  if (!s.loaded) {
    g_failed = true;
    state.SkipWithError(("the nu = 0.49 beam did not load: " + s.errors).c_str());
    return;
  }
  // The first step builds the matrix pattern, the grids, P and the first coarse operators:
  // timed apart, so that steps/s is the rate of the steps that follow.
  const double firstStart = cpuSeconds();
  if (!s.scene->step()) {
    g_failed = true;
    state.SkipWithError("the first step failed");
    return;
  }
  state.counters["first_step_cpu_s"] = cpuSeconds() - firstStart;
  // Steps timed one by one (processor time), the error of the next step's solve measured every
  // 10 steps and at the end, outside the timing.
  const int steps = benchSteps();
  long long total = 0;
  double seconds = 0, worst = 0, last = 0, referenceResidual = 0;
  for (auto _ : state) {
    for (int n = 1; n <= steps; ++n) {
      const double start = cpuSeconds();
      if (!s.scene->step()) {
        g_failed = true;
        state.SkipWithError("a step failed");
        return;
      }
      seconds += cpuSeconds() - start;
      if (n % 10 == 0 || n == steps) {
        last = nextSolveError(s, referenceResidual);
        worst = std::max(worst, last);
      }
    }
    total += steps;
  }
  state.counters["cpu_steps/s"] = double(total) / seconds;
  state.counters["error"] = last;
  state.counters["error_max"] = worst;
  state.counters["reference_residual"] = referenceResidual;
}

void registerAll() {
  for (const char* name :
       {"CGfast", "CGmax", "MG1", "MG2", "MG3", "MG4", "FMG4", "MG4-FCG5", "MG4-FCG10"})
    benchmark::RegisterBenchmark((std::string("Table52/") + name).c_str(),
                                 [name](benchmark::State& state) { table52Method(state, name); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(3);
  benchmark::RegisterBenchmark("Table52/Summary", table52Summary)->Iterations(1);
  for (const KernelMethod& method : kKernelMethods)
    benchmark::RegisterBenchmark(
        (std::string("Table52Assembled/") + method.name).c_str(),
        [&method](benchmark::State& state) { kernelTable52Method(state, method); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(5);
  const char* const storages[] = {"eigen", "blocks-double", "blocks-single"};
  for (int storage = 0; storage < 3; ++storage)
    benchmark::RegisterBenchmark(
        (std::string("Table52Assembled/Product-") + storages[storage]).c_str(),
        [storage](benchmark::State& state) { kernelTable52Product(state, storage); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(20);
  benchmark::RegisterBenchmark("Table52Assembled/Chart", kernelTable52Chart)->Iterations(1);
  for (const Beam049Setting& setting : kBeam049Settings)
    benchmark::RegisterBenchmark((std::string("Beam049/") + setting.name).c_str(),
                                 [&setting](benchmark::State& state) { beam049(state, setting); })
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
