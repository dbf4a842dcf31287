// SPDX-License-Identifier: MIT
// Cost per element of the corotational kernels, over 4096 elements stored contiguously as a
// force field would store them. Run: build/tests/FemKernels_benchmark; the per_element counter
// (seconds per element) is the figure to quote.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "FemTestUtilities.h"
#include "SolidMechanics/kernels/CorotationalHexahedron.h"
#include "SolidMechanics/kernels/CorotationalTetrahedron.h"

namespace stroma::fem {
namespace {

constexpr int kElements = 4096;

template <class Element>
struct Mesh {
  std::vector<Element> elements;
  std::vector<typename Element::Vectors> positions;
  std::vector<Eigen::Matrix3d> rotations;
};

template <class Element, class Build>
const Mesh<Element>& makeMesh(const typename Element::Vectors& shape, Build&& build) {
  static Mesh<Element> mesh = [&] {
    Mesh<Element> m;
    std::mt19937 rng(42);
    const Matrix6d C = test::testElasticity(5000, 0.45);
    for (int e = 0; e < kElements; ++e) {
      const typename Element::Vectors rest =
          shape + test::randomVectors<Element::nodeCount>(rng, 0.05);
      Element element;
      if (build(rest, C, element) != ElementStatus::ok) continue;
      m.elements.push_back(element);
      m.positions.push_back(test::randomDeformedState<Element::nodeCount>(rng, rest, 0.1, 0.05));
      m.rotations.push_back(computeRotation(RotationMethod::polar, element, m.positions.back()));
    }
    return m;
  }();
  return mesh;
}

const Mesh<CorotationalTetrahedron>& tetrahedra() {
  return makeMesh<CorotationalTetrahedron>(test::irregularTetrahedron(),
                                           computeCorotationalTetrahedron);
}
const Mesh<CorotationalHexahedron>& hexahedra() {
  return makeMesh<CorotationalHexahedron>(test::unitCube(), computeCorotationalHexahedron);
}

void setPerElement(benchmark::State& state, std::size_t count) {
  // Printed as seconds per element with an SI prefix ("42.1n" = 42.1 ns).
  state.counters["per_element"] =
      benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

/// Rotation then force, what addForce does per element.
template <class Element>
void rotationAndForce(benchmark::State& state, const Mesh<Element>& mesh) {
  const auto method = static_cast<RotationMethod>(state.range(0));
  state.SetLabel(std::string(rotationMethodName(method)));
  for (auto _ : state) {
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
      const Eigen::Matrix3d R = computeRotation(method, mesh.elements[e], mesh.positions[e]);
      auto f = computeForce(mesh.elements[e], R, mesh.positions[e]);
      benchmark::DoNotOptimize(f.data());
    }
  }
  setPerElement(state, mesh.elements.size());
}

void BM_TetrahedronForce(benchmark::State& state) { rotationAndForce(state, tetrahedra()); }
void BM_HexahedronForce(benchmark::State& state) { rotationAndForce(state, hexahedra()); }

/// R Ke R^T for an implicit solve's assembled matrix (rotation already known).
void BM_TetrahedronStiffness(benchmark::State& state) {
  const auto& mesh = tetrahedra();
  Matrix12d K;
  for (auto _ : state) {
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
      K = computeStiffness(mesh.elements[e], mesh.rotations[e]);
      benchmark::DoNotOptimize(K.data());
    }
  }
  setPerElement(state, mesh.elements.size());
}

/// R Ke R^T of hexahedra sharing one Ke (a grid, CorotationalElements), rotations varying.
void BM_HexahedronStiffness(benchmark::State& state) {
  const auto& mesh = hexahedra();
  const Matrix24d& Ke = mesh.elements.front().stiffness;
  Matrix24d K;
  for (auto _ : state) {
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
      K = computeStiffness<8>(Ke, mesh.rotations[e]);
      benchmark::DoNotOptimize(K.data());
    }
  }
  setPerElement(state, mesh.elements.size());
}

/// df = -R Ke R^T dx, what addDForce does per element (matrix-free CG iteration).
void BM_TetrahedronDForce(benchmark::State& state) {
  const auto& mesh = tetrahedra();
  for (auto _ : state) {
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
      auto df = computeDForce(mesh.elements[e], mesh.rotations[e], mesh.positions[e]);
      benchmark::DoNotOptimize(df.data());
    }
  }
  setPerElement(state, mesh.elements.size());
}

constexpr int kSmall = static_cast<int>(RotationMethod::small);
constexpr int kSvd = static_cast<int>(RotationMethod::svd);
BENCHMARK(BM_TetrahedronForce)->DenseRange(kSmall, kSvd);
BENCHMARK(BM_HexahedronForce)->DenseRange(kSmall, kSvd);
BENCHMARK(BM_TetrahedronStiffness);
BENCHMARK(BM_HexahedronStiffness);
BENCHMARK(BM_TetrahedronDForce);

}  // namespace
}  // namespace stroma::fem

BENCHMARK_MAIN();
