// SPDX-License-Identifier: MIT
// stroma-bench-precomputed: Cotin's precomputed linear model (plugins/Precomputed) beside seed
// 000 table 2.1 (a liver of 614 surface nodes on a Pentium II 450 MHz: 3120 Hz for a force on
// one node, 30 Hz for imposed displacements on 20 nodes). bench/README.md has the numbers.
//
// The mesh: share/mesh/organ.msh (935 points, 3579 tetrahedra, 643 surface points), E = 3 kPa,
// nu = 0.45, hung by the 21 points of OrganPulled.scn's attachment box; basis = the 622 free
// surface points, every row kept (deformedRegion="all") or the surface rows only.
//
// Precompute: assembly of K, sparse LDL^T, 3 x 622 solves (seconds; counters: nodes, basis
//   nodes, stored_MB = the cache file's size).
// ForceOnOneNode/<rows>: u of every row node (rows: surfaceOnly 0 = all 935, 1 = the 643 surface)
// for a force on one surface point (superposition of
//   3 columns), a different point each iteration.
// Imposed/<rows>/<m>: u for imposed displacements on the first m of the 20 points of
//   OrganImposed.scn (m = 1, 5, 10, 20, table 2.1's rows), new values each iteration (the
//   3m x 3m factorisation is kept: per step O(m^2 + m r)), with the reaction forces.
//   ImposedRefactor: 20 points, one of them changed each time, so that it refactorises.
// SceneStep: one step of scenes/precomputed/OrganPulled.scn through the framework (the loads
//   gathered from ConstantForceField, positions written), basis from the cache.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <sstream>
#include <string>

#include "Precomputed/kernels/BasisCache.h"
#include "Precomputed/kernels/DeformationBasis.h"
#include "Precomputed/kernels/LinearStiffnessAssembly.h"
#include "core/Runtime.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"
#include "topology/Topology.h"

namespace stroma::bench {
namespace {

using precomputed::DeformationBasis;

const char* kOrgan = R"(<Node name="root" dt="0.02" gravity="0 0 0">
  <Node name="Organ">
    <MeshGmshLoader name="loader" filename="mesh/organ.msh" />
    <TetrahedronSetTopologyContainer name="topology" src="@loader" />
    <MechanicalObject name="dofs" template="Vec3" src="@loader" />
    <BoxROI name="attachment" box="-0.11 0.042 -0.02  -0.07 0.06 0.03"
            position="@dofs.rest_position" />
  </Node>
</Node>)";

const std::vector<int> kImposed{10,  11,  12,  13,  14,  58,  60,  102, 103, 202,
                                210, 228, 229, 234, 235, 236, 248, 270, 278, 280};

/// The organ's mesh, boundary and basis, computed once.
struct Organ {
  std::vector<Vec3d> points;
  std::vector<precomputed::TetrahedronNodes> tetrahedra;
  std::vector<int> fixedDofs, basisNodes, surfaceNodes;
  std::unique_ptr<DeformationBasis> all, surface;
  std::string error;

  Organ() {
    Runtime runtime;
    Scene scene(runtime);
    if (!scene.loadString(kOrgan, std::filesystem::path(STROMA_SOURCE_DIR) / "bench/organ.scn")) {
      error = "the organ scene did not load";
      return;
    }
    const Node* node = scene.root().findChild("Organ");
    const auto* topology = node ? node->get<Topology>() : nullptr;
    const auto* box = node ? node->findObject("attachment") : nullptr;
    if (!topology || !box) {
      error = "no topology or attachment";
      return;
    }
    points = topology->positions();
    tetrahedra.assign(topology->tetrahedra().begin(), topology->tetrahedra().end());
    std::vector<char> fixed(points.size(), 0), onSurface(points.size(), 0);
    std::istringstream indices(box->findData("indices")->valueText());
    for (int i; indices >> i;) {
      fixed[size_t(i)] = 1;
      for (int c = 0; c < 3; ++c) fixedDofs.push_back(3 * i + c);
    }
    for (const Triangle& t : topology->boundaryTriangles())
      for (Index i : t) onSurface[i] = 1;
    for (int i = 0; i < int(points.size()); ++i) {
      if (onSurface[size_t(i)]) surfaceNodes.push_back(i);
      if (onSurface[size_t(i)] && !fixed[size_t(i)]) basisNodes.push_back(i);
    }
    all = compute(error);
    if (all) {
      auto restricted = all->restrictedTo(surfaceNodes, error);
      if (restricted) surface = std::make_unique<DeformationBasis>(std::move(*restricted));
    }
  }

  std::unique_ptr<DeformationBasis> compute(std::string& why) const {
    precomputed::SparseMatrix K;
    if (!precomputed::assembleLinearStiffness(points, tetrahedra, 3000, 0.45, K, why))
      return nullptr;
    auto basis = DeformationBasis::compute(K, fixedDofs, basisNodes, why);
    return basis ? std::make_unique<DeformationBasis>(std::move(*basis)) : nullptr;
  }
};

Organ& organ() {
  static Organ instance;
  return instance;
}

bool ready(benchmark::State& state) {
  if (organ().all && organ().surface) return true;
  state.SkipWithError(("organ basis: " + organ().error).c_str());
  return false;
}

void Precompute(benchmark::State& state) {
  if (!ready(state)) return;
  std::unique_ptr<DeformationBasis> basis;
  for (auto _ : state) {
    std::string error;
    basis = organ().compute(error);
    if (!basis) state.SkipWithError(error.c_str());
  }
  state.counters["nodes"] = double(organ().points.size());
  state.counters["basis_nodes"] = double(organ().basisNodes.size());
  if (basis) state.counters["stored_MB"] = double(precomputed::basisCacheBytes(*basis)) / 1e6;
  state.counters["surface_stored_MB"] =
      double(precomputed::basisCacheBytes(*organ().surface)) / 1e6;
}
BENCHMARK(Precompute)->Unit(benchmark::kSecond)->Iterations(1);

const DeformationBasis& basisOf(const benchmark::State& state) {
  return state.range(0) == 0 ? *organ().all : *organ().surface;
}

void ForceOnOneNode(benchmark::State& state) {
  if (!ready(state)) return;
  const DeformationBasis& basis = basisOf(state);
  precomputed::VectorXd u(basis.columns().rows());
  std::vector<int> node{0};
  std::vector<precomputed::Vec3> force{precomputed::Vec3(0, -0.2, 0.05)};
  std::string error;
  size_t next = 0;
  for (auto _ : state) {
    node[0] = organ().basisNodes[next++ % organ().basisNodes.size()];
    basis.displacementFromForces(node, force, u, error);
    benchmark::DoNotOptimize(u.data());
  }
  state.counters["rows"] = double(basis.rowNodes().size());
  state.counters["Hz"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(ForceOnOneNode)->ArgName("surfaceOnly")->Arg(0)->Arg(1);

void imposed(benchmark::State& state, bool refactor) {
  if (!ready(state)) return;
  const DeformationBasis& basis = basisOf(state);
  precomputed::VectorXd u(basis.columns().rows());
  const std::vector<int> imposedNodes(kImposed.begin(), kImposed.begin() + state.range(1));
  std::vector<precomputed::Vec3> d(imposedNodes.size()), reactions;
  std::string error;
  double s = 0;
  size_t step = 0;
  const int factorizationsBefore = basis.imposedFactorizationCount();
  for (auto _ : state) {
    s += 1e-4;
    ++step;
    for (auto& v : d) v = precomputed::Vec3(-s, -0.5 * s, 0);
    if (refactor) {  // a different set each time: the factorisation is redone
      auto nodes = imposedNodes;
      nodes[0] = organ().basisNodes[300 + step % 300];
      if (!basis.displacementFromImposed(nodes, d, u, reactions, error)) break;
    } else if (!basis.displacementFromImposed(imposedNodes, d, u, reactions, error)) {
      break;
    }
    benchmark::DoNotOptimize(u.data());
  }
  if (!error.empty()) state.SkipWithError(error.c_str());
  state.counters["factorizations"] =
      double(basis.imposedFactorizationCount() - factorizationsBefore);
  state.counters["rows"] = double(basis.rowNodes().size());
  state.counters["Hz"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
void Imposed(benchmark::State& state) { imposed(state, false); }
void ImposedRefactor(benchmark::State& state) { imposed(state, true); }
BENCHMARK(Imposed)->ArgNames({"surfaceOnly", "nodes"})->ArgsProduct({{0, 1}, {1, 5, 10, 20}});
BENCHMARK(ImposedRefactor)->ArgNames({"surfaceOnly", "nodes"})->Args({0, 20});

void SceneStep(benchmark::State& state) {
  Runtime runtime;
  Scene scene(runtime);
  const auto file = std::filesystem::path(STROMA_SOURCE_DIR) / "scenes/precomputed/OrganPulled.scn";
  if (!scene.loadFile(file)) {
    state.SkipWithError("OrganPulled.scn did not load");
    return;
  }
  for (auto _ : state)
    if (!scene.step()) state.SkipWithError("step failed");
  state.counters["Hz"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(SceneStep);

}  // namespace
}  // namespace stroma::bench

BENCHMARK_MAIN();
