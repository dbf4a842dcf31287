// SPDX-License-Identifier: MIT
// CorotationalElements<Element>: the per-element arrays and the parallel loops that the
// corotational FEM force fields share (TetrahedronFEMForceField, HexahedronFEMForceField,
// HexahedronFEMForceFieldAndMass). It wires the kernels of SolidMechanics/kernels
// (CorotationalElement.h: f = -R Ke (R^T x - X), df = -R Ke R^T dx, E = 1/2 u^T Ke u) to state
// vectors, and knows nothing of Data, nodes or messages: the components own one and report.
//
// Layout. Per-element constants (rest shape, Ke, rest frame) are computed once into one
// contiguous array; rotations and per-corner results are arrays of the step, sized once.
//
// Shared constants (hexahedra). Elements that are the same rest shape up to a translation,
// with the same Young modulus, share one entry of the constants (kernels/EqualElements.h): a
// regular or sparse grid has one entry for all its elements, so forces, products and assembly
// read one 24 x 24 Ke from cache instead of one per element from memory (151 MB for 32^3
// elements). The constants read by the kernels (Ke, rest frame, centre gradients, volume) do
// not depend on a translation; each element keeps its own rest positions (restPositions(e)),
// from which its displacement is taken, so a rest state gives exactly zero force. The results
// equal those of one entry per element to round-off (EqualElements.h bounds the difference).
//
// Determinism. Every loop over elements writes only its own element's slots (its rotation, the
// N "corner" vectors of its result); a second loop over vertices then sums, for each vertex,
// the corners of the elements around it in increasing element order (the vertex -> corners
// adjacency built at setElements). No two threads write the same value and every sum has a
// fixed order, so the results are bit-for-bit the same for any thread count.
//
// Tetrahedra. Forces and products use Ke in factored form (multiplyFactoredStiffness:
// Ke = B(G)^T C B(G), 12 numbers per element and one C for all), the product on rows of 4
// nodes (one AVX register per coordinate): it reads 96 bytes per element instead of Ke's 1152
// and vectorizes across the nodes, 1.6 times faster per element than R Ke R^T dx with Eigen's
// 12 x 12 product (bench/README.md). Energy and assembly keep Ke. The two forms agree to
// round-off, not bit for bit; results stay the same for any thread count.
//
// Tetrahedra, several products at one point. The products of an iterative solve share the
// rotations of one addForce; from the second product at a point (or the first, when the last
// point had several) K's 3 x 3 blocks are refilled once and the products are block-row products
// (kernels/TetrahedronStiffnessBlocks.h): on SOFA's liver (596 tetrahedra, 18 products per
// step) a product took 14 us through the elements, 2.4 us through the blocks, a refill
// 22 us (perf, 5000 steps). The blocks and the element loop agree to round-off.
//
// Rotations. addForce computes each element's rotation at the positions it is given and keeps
// it; addDForce and addKToMatrix of the same step use those rotations (the linearization point
// of an implicit step is where the forces were last computed), as SOFA does.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "SolidMechanics/kernels/CorotationalElement.h"
#include "SolidMechanics/kernels/CorotationalHexahedron.h"
#include "SolidMechanics/kernels/CorotationalTetrahedron.h"
#include "SolidMechanics/kernels/EqualElements.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "SolidMechanics/kernels/TetrahedronStiffnessBlocks.h"
#include "SolidMechanics/kernels/VolumetricSplit.h"
#include "core/ThreadPool.h"
#include "core/Types.h"
#include "linalg/AssembledMatrix.h"
#include "topology/TopologyChange.h"
#include "topology/TopologyTypes.h"

namespace stroma {

template <class Element>
class CorotationalElements {
 public:
  static constexpr int N = Element::nodeCount;
  using Vectors = typename Element::Vectors;
  using Indices = std::array<Index, N>;
  using Matrix = fem::ElementMatrix<N>;

  static_assert(N == 4 || N == 8,
                "CorotationalElements takes fem::CorotationalTetrahedron or "
                "fem::CorotationalHexahedron.");
  /// Hexahedra share their constants between equal elements; tetrahedra keep one entry per
  /// element (their forces and products use per-element factors, AveragedNodalPressure reads
  /// constants()[e]).
  static constexpr bool kSharesConstants = N == 8;

  /// Work per task of the parallel loops, chosen so that a task lasts 10 to 100 us: a loop no
  /// longer than one task runs on the calling thread alone, since waking a second thread and
  /// waiting for it at the end costs tens of microseconds (more on a machine whose cores are
  /// shared). Rotation and force (or stiffness): 0.1 to 1 us per element.
  static constexpr std::size_t kGrain = 128;
  /// The product -R Ke R^T dx: about 20 ns per tetrahedron (factored form), about 280 ns
  /// per hexahedron (24 x 24 Ke). The products of a CG solve on a few thousand
  /// tetrahedra then stay on one thread (measured with Ke on the organ scene, 3579 tetrahedra:
  /// 0.13 ms per product on one thread, 0.16 ms on two).
  static constexpr std::size_t kProductGrain = N == 4 ? 4096 : 512;
  /// Sums per vertex: 20 to 50 ns each (the corners of 4 to 24 elements).
  static constexpr std::size_t kVertexGrain = 2048;
  /// Block rows of the stiffness blocks (tetrahedra): about 11 blocks, 30 to 50 ns per row.
  static constexpr std::size_t kBlockRowGrain = 2048;
  /// Elements whose stiffness matrices are computed together (in parallel) before being added
  /// to the (sequential) matrix accumulator: bounds the scratch to kMatrixBatch matrices.
  static constexpr std::size_t kMatrixBatch = 512;

  /// What computeConstants found in the rest shape, as element indices in increasing order.
  struct RestShapeReport {
    std::vector<Index> degenerate;  ///< (nearly) zero volume: the element is left out (Ke = 0)
    std::vector<Index> inverted;    ///< negative volume (vertex order): used with |V|
  };

  /// Takes the elements (indices < pointCount, checked by the caller) and builds the vertex
  /// adjacency and the arrays of the step. Allocates; call from init.
  void setElements(std::span<const Indices> elements, std::size_t pointCount) {
    m_elements.assign(elements.begin(), elements.end());
    const std::size_t count = m_elements.size();
    m_constants.assign(kSharesConstants ? 0 : count, Element{});
    m_constantIndex.assign(kSharesConstants ? count : 0, 0);
    m_restPositions.assign(kSharesConstants ? count : 0, Vectors::Zero());
    m_rotations.assign(count, Eigen::Matrix3d::Identity());
    m_corners.assign(count * N, Vec3d::Zero());
    m_matrices.clear();
    m_degenerate.assign(count, 0);
    if constexpr (N == 4) m_stiffnessFactors.assign(count, fem::TetrahedronRows{});
    buildVertexAdjacency(pointCount);
    resetStiffnessBlocks();
  }

  /// Follows the removal of elements at run time (cutting; topology/TopologyChange.h: each
  /// removed slot, in the order of `removed`, receives the last element): the constants,
  /// rotations and stiffness factors of the kept elements move with them and nothing is
  /// recomputed; the vertex adjacency is rebuilt (a counting sort, linear in the elements, no
  /// element computation). The results equal those of setElements and computeConstants on the
  /// remaining elements, bit for bit for tetrahedra; to round-off for hexahedra (a shared
  /// entry may have been computed from an element of its group that is gone).
  void removeElements(std::span<const Index> removed) {
    applyRemoval(m_elements, removed);
    if constexpr (kSharesConstants) {
      applyRemoval(m_constantIndex, removed);  // the shared entries stay, some maybe unused
      applyRemoval(m_restPositions, removed);
    } else {
      applyRemoval(m_constants, removed);
    }
    applyRemoval(m_rotations, removed);
    if constexpr (N == 4) applyRemoval(m_stiffnessFactors, removed);
    m_corners.resize(m_elements.size() * N);
    m_degenerate.resize(m_elements.size());
    buildVertexAdjacency(pointCount());
    resetStiffnessBlocks();
  }

  std::size_t size() const { return m_elements.size(); }
  std::size_t pointCount() const { return m_vertexOffsets.size() - 1; }
  const std::vector<Indices>& elements() const { return m_elements; }
  /// The constants of element e (shared with the elements equal to it, for hexahedra).
  const Element& constant(std::size_t e) const {
    if constexpr (kSharesConstants)
      return m_constants[m_constantIndex[e]];
    else
      return m_constants[e];
  }
  /// Tetrahedra: the constants of each element, in element order.
  const std::vector<Element>& constants() const
    requires(!kSharesConstants)
  {
    return m_constants;
  }
  /// The rest positions of element e (m).
  const Vectors& restPositions(std::size_t e) const {
    if constexpr (kSharesConstants)
      return m_restPositions[e];
    else
      return m_constants[e].restPositions;
  }
  /// How many distinct constants are stored (for hexahedra: 1 for a uniform grid; for
  /// tetrahedra: one per element).
  std::size_t distinctConstantCount() const { return m_constants.size(); }
  /// The rotation of each element at the positions of the last addForce (or updateRotations).
  const std::vector<Eigen::Matrix3d>& rotations() const { return m_rotations; }

  /// How the volumetric energy enters Ke (VolumetricSplit.h): full by default; meanDilatation
  /// for hexahedra only; deviatoric when a mesh-level term adds it (AveragedNodalPressure.h).
  /// Takes effect at the next computeConstants.
  void setVolumetricStiffness(fem::VolumetricStiffness volumetric) { m_volumetric = volumetric; }
  fem::VolumetricStiffness volumetricStiffness() const { return m_volumetric; }

  /// Computes every element's constants from the rest positions, the Young modulus (one value,
  /// or one per element) and Poisson's ratio (both valid: checked by the caller). Degenerate
  /// elements get Ke = 0 and are listed. Hexahedra: equal elements are found first and their
  /// constants computed once (allocates the groups).
  RestShapeReport computeConstants(std::span<const Vec3d> rest,
                                   std::span<const double> youngModulus, double poissonRatio,
                                   const ThreadPool& pool) {
    const bool uniform = youngModulus.size() == 1;
    // The elements' own C: all of it, or its deviatoric part (VolumetricSplit.h).
    const auto elasticity = [this, poissonRatio](double E) {
      const fem::LameParameters lame = fem::computeLameParameters(E, poissonRatio);
      return m_volumetric == fem::VolumetricStiffness::full
                 ? fem::computeElasticityMatrix(lame)
                 : fem::computeDeviatoricElasticityMatrix(lame);
    };
    const fem::Matrix6d uniformC = elasticity(youngModulus[0]);
    // One entry of the constants from rest positions X and modulus E; true when degenerate.
    const auto computeEntry = [&](const Vectors& X, double E, Element& element) {
      const fem::Matrix6d C = uniform ? uniformC : elasticity(E);
      fem::ElementStatus status;
      if constexpr (N == 4) {
        status = fem::computeCorotationalTetrahedron(X, C, element);
      } else {
        status = fem::computeCorotationalHexahedron(X, C, element);
        if (status == fem::ElementStatus::ok &&
            m_volumetric == fem::VolumetricStiffness::meanDilatation)
          status = addMeanDilatation(X, fem::computeLameParameters(E, poissonRatio), element);
      }
      if (status == fem::ElementStatus::ok) return false;
      // Left out of the mechanics: zero stiffness, rest shape kept for the rotations.
      element = Element{};
      element.restPositions = X;
      return true;
    };
    std::vector<char>& degenerate = m_degenerate;  // per entry of m_constants
    if constexpr (kSharesConstants) {
      pool.parallelFor(size(), kGrain, [&](std::size_t begin, std::size_t end) {
        for (std::size_t e = begin; e < end; ++e) m_restPositions[e] = gather(rest, e);
      });
      const fem::ElementGroups groups =
          fem::groupEqualElements<N>(std::span<const Vectors>(m_restPositions), youngModulus);
      m_constantIndex.assign(groups.groupOf.begin(), groups.groupOf.end());
      m_constants.assign(groups.representative.size(), Element{});
      degenerate.assign(m_constants.size(), 0);
      pool.parallelFor(m_constants.size(), kGrain, [&](std::size_t begin, std::size_t end) {
        for (std::size_t g = begin; g < end; ++g) {
          const std::size_t e = groups.representative[g];
          degenerate[g] = computeEntry(m_restPositions[e], youngModulus[uniform ? 0 : e],
                                       m_constants[g]);
        }
      });
    } else {
      // C(E) = E C(1) for one Poisson ratio: G carries sqrt(E_e |V_e|).
      m_unitElasticity = elasticity(1.0);
      m_unitLame = fem::findLameParameters(m_unitElasticity);
      m_blocksCurrent = false;
      degenerate.assign(size(), 0);
      pool.parallelFor(size(), kGrain, [&](std::size_t begin, std::size_t end) {
        for (std::size_t e = begin; e < end; ++e) {
          const double E = youngModulus[uniform ? 0 : e];
          degenerate[e] = computeEntry(gather(rest, e), E, m_constants[e]);
          m_stiffnessFactors[e] =
              fem::computeStiffnessFactor(m_constants[e], degenerate[e] ? 0.0 : E);
        }
      });
    }
    RestShapeReport report;
    for (std::size_t e = 0; e < size(); ++e) {
      const std::size_t entry = kSharesConstants ? m_constantIndex[e] : e;
      if (degenerate[entry])
        report.degenerate.push_back(static_cast<Index>(e));
      else if (m_constants[entry].restVolume < 0)
        report.inverted.push_back(static_cast<Index>(e));
    }
    return report;
  }

  /// Rotations at positions x, without forces (at init, so that addDForce is defined before
  /// the first addForce).
  void updateRotations(fem::RotationMethod method, std::span<const Vec3d> x,
                       const ThreadPool& pool) {
    pool.parallelFor(size(), kGrain, [&](std::size_t begin, std::size_t end) {
      for (std::size_t e = begin; e < end; ++e)
        m_rotations[e] = fem::computeRotation(method, constant(e), gather(x, e));
    });
    startLinearizationPoint();
  }

  /// f += elastic forces at x (N); keeps the rotations.
  void addForce(fem::RotationMethod method, std::span<const Vec3d> x, std::span<Vec3d> f,
                const ThreadPool& pool) {
    forEachElement(pool, kGrain, [&](std::size_t e, Eigen::Map<Vectors> corner) {
      const Vectors xe = gather(x, e);
      const Element& element = constant(e);
      const Eigen::Matrix3d R = fem::computeRotation(method, element, xe);
      m_rotations[e] = R;
      if constexpr (N == 4)
        storeRows(corner, fem::computeFactoredForce(m_stiffnessFactors[e], m_unitElasticity, R,
                                                    fem::toRows(xe),
                                                    fem::toRows(element.restPositions)));
      else
        corner = fem::computeForce<N>(element.stiffness, m_restPositions[e], R, xe);
    });
    sumCorners(f, 1.0, pool);
    startLinearizationPoint();
  }

  /// df += kFactor K dx with K = -R Ke R^T (N/m), the rotations of the last addForce.
  void addDForce(std::span<const Vec3d> dx, std::span<Vec3d> df, double kFactor,
                 const ThreadPool& pool) {
    if constexpr (N == 4) {
      if (useStiffnessBlocks(pool)) {
        const struct {
          std::span<const Vec3d> dx;
          std::span<Vec3d> df;
          double factor;
        } product{dx, df, -kFactor};
        pool.parallelFor(std::min(df.size(), pointCount()), kBlockRowGrain,
                         [this, &product](std::size_t begin, std::size_t end) {
                           m_stiffnessBlocks.multiply(product.dx, product.df, product.factor,
                                                      begin, end);
                         });
        return;
      }
      forEachElement(pool, kProductGrain, [&](std::size_t e, Eigen::Map<Vectors> corner) {
        storeRows(corner, fem::computeFactoredDForce(m_stiffnessFactors[e], m_unitElasticity,
                                                     m_rotations[e], gatherRows(dx, e)));
      });
    } else {
      forEachElement(pool, kProductGrain, [&](std::size_t e, Eigen::Map<Vectors> corner) {
        corner = fem::computeDForce<N>(constant(e).stiffness, m_rotations[e], gather(dx, e));
      });
    }
    sumCorners(df, kFactor, pool);
  }

  /// Adds kFactor K = -kFactor R Ke R^T, this state's first row at `offset`: element matrices
  /// are computed in parallel batches, then added in element order (the accumulator is
  /// sequential and its pattern must repeat from step to step).
  void addKToMatrix(MatrixAccumulator& matrix, std::size_t offset, double kFactor,
                    const ThreadPool& pool) {
    if (size() == 0 || kFactor == 0) return;
    if (m_matrices.empty()) m_matrices.resize(std::min(size(), kMatrixBatch));
    for (std::size_t first = 0; first < size(); first += kMatrixBatch) {
      const std::size_t count = std::min(kMatrixBatch, size() - first);
      pool.parallelFor(count, kGrain / 4, [this, first](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k)
          m_matrices[k] =
              fem::computeStiffness<N>(constant(first + k).stiffness, m_rotations[first + k]);
      });
      for (std::size_t k = 0; k < count; ++k)
        addElementMatrix(matrix, offset, first + k, -kFactor, m_matrices[k]);
    }
  }

  /// Adds factor * (M (x) I_3) for one N x N matrix M per element (a consistent mass).
  template <class NodalMatrices>
  void addNodalMatrices(MatrixAccumulator& matrix, std::size_t offset, double factor,
                        const NodalMatrices& perElement) const {
    for (std::size_t e = 0; e < size(); ++e) {
      const Indices& nodes = m_elements[e];
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
          const double value = factor * perElement[e](i, j);
          for (std::size_t k = 0; k < 3; ++k)
            matrix.add(offset + 3 * nodes[i] + k, offset + 3 * nodes[j] + k, value);
        }
    }
  }

  /// Potential energy sum 1/2 u^T Ke u (J) at x, rotations computed at x (not kept). Summed
  /// sequentially in element order.
  double energy(fem::RotationMethod method, std::span<const Vec3d> x) const {
    double total = 0;
    for (std::size_t e = 0; e < size(); ++e) {
      const Vectors xe = gather(x, e);
      const Element& element = constant(e);
      total += fem::computeEnergy<N>(element.stiffness, restPositions(e),
                                     fem::computeRotation(method, element, xe), xe);
    }
    return total;
  }

  /// out += factor * (sum over the elements of each vertex of the corners written by
  /// perElement(e, corner)): the deterministic element-then-vertex pattern, for any
  /// per-element product (forces, stiffness or mass times a vector).
  template <class PerElement>
  void accumulate(std::span<Vec3d> out, double factor, const ThreadPool& pool,
                  PerElement&& perElement) {
    forEachElement(pool, kProductGrain, perElement);
    sumCorners(out, factor, pool);
  }

  /// The element's nodal vectors taken from a state vector.
  Vectors gather(std::span<const Vec3d> v, std::size_t e) const {
    Vectors result;
    const Indices& nodes = m_elements[e];
    for (int i = 0; i < N; ++i) result.col(i) = v[nodes[i]];
    return result;
  }

 private:
  /// Ke += kappa V bbar bbar^T on a hexahedron whose Ke was computed with C_dev.
  static fem::ElementStatus addMeanDilatation(const Vectors& X, const fem::LameParameters& lame,
                                              Element& element) {
    Vectors meanGradients;
    double volume = 0;
    if (fem::computeHexahedronMeanGradients(X, meanGradients, volume) != fem::ElementStatus::ok)
      return fem::ElementStatus::degenerate;
    fem::addMeanDilatationStiffness<N>(meanGradients, volume, fem::computeBulkModulus(lame),
                                       element.stiffness);
    return fem::ElementStatus::ok;
  }

  /// The stiffness blocks' pattern for the current elements (tetrahedra; allocates), and no
  /// product history.
  void resetStiffnessBlocks() {
    if constexpr (N == 4) {
      m_stiffnessBlocks.setPattern(
          std::span<const fem::TetrahedronStiffnessBlocks::Tetrahedron>(m_elements),
          pointCount());
    }
    m_blocksCurrent = false;
    m_productsAtPoint = m_productsAtLastPoint = 0;
  }

  /// New rotations: the blocks are stale.
  void startLinearizationPoint() {
    m_productsAtLastPoint = m_productsAtPoint;
    m_productsAtPoint = 0;
    m_blocksCurrent = false;
  }

  /// Whether this product goes through the stiffness blocks, refilled first if stale. A refill
  /// costs about 1.6 element-loop products: it is done from the second product at a
  /// point, or from the first when the last point had several (a CG solve per step).
  bool useStiffnessBlocks(const ThreadPool& pool) {
    ++m_productsAtPoint;
    if (!m_unitLame) return false;  // not isotropic: the element loop
    if (m_blocksCurrent) return true;
    if (m_productsAtPoint < 2 && m_productsAtLastPoint < 2) return false;
    pool.parallelFor(size(), kGrain, [this](std::size_t begin, std::size_t end) {
      m_stiffnessBlocks.rotateFactors(m_rotations, m_stiffnessFactors, begin, end);
    });
    pool.parallelFor(pointCount(), kBlockRowGrain / 4, [this](std::size_t begin, std::size_t end) {
      m_stiffnessBlocks.fillUpperBlocks(*m_unitLame, begin, end);
    });
    pool.parallelFor(pointCount(), kBlockRowGrain, [this](std::size_t begin, std::size_t end) {
      m_stiffnessBlocks.fillLowerBlocks(begin, end);
    });
    m_blocksCurrent = true;
    return true;
  }

  /// Vertex -> corners (e * N + local), by a counting sort: increasing element order.
  void buildVertexAdjacency(std::size_t pointCount) {
    m_vertexOffsets.assign(pointCount + 1, 0);
    for (const Indices& element : m_elements)
      for (Index v : element) ++m_vertexOffsets[v + 1];
    for (std::size_t v = 0; v < pointCount; ++v) m_vertexOffsets[v + 1] += m_vertexOffsets[v];
    m_vertexCorners.resize(m_vertexOffsets[pointCount]);
    std::vector<Index> next(m_vertexOffsets.begin(), m_vertexOffsets.end() - 1);
    for (std::size_t e = 0; e < m_elements.size(); ++e)
      for (int i = 0; i < N; ++i)
        m_vertexCorners[next[m_elements[e][i]]++] = static_cast<Index>(e * N + i);
  }

  /// gather() by coordinate rows, for tetrahedra.
  fem::TetrahedronRows gatherRows(std::span<const Vec3d> v, std::size_t e) const {
    const Indices& n = m_elements[e];
    const Vec3d &p0 = v[n[0]], &p1 = v[n[1]], &p2 = v[n[2]], &p3 = v[n[3]];
    return {Eigen::Array4d(p0.x(), p1.x(), p2.x(), p3.x()),
            Eigen::Array4d(p0.y(), p1.y(), p2.y(), p3.y()),
            Eigen::Array4d(p0.z(), p1.z(), p2.z(), p3.z())};
  }

  static void storeRows(Eigen::Map<Vectors> corner, const fem::TetrahedronRows& rows) {
    for (int i = 0; i < 4; ++i) corner.col(i) = Vec3d(rows[0][i], rows[1][i], rows[2][i]);
  }

  template <class PerElement>
  void forEachElement(const ThreadPool& pool, std::size_t grain, PerElement&& perElement) {
    pool.parallelFor(size(), grain, [this, &perElement](std::size_t begin, std::size_t end) {
      for (std::size_t e = begin; e < end; ++e)
        perElement(e, Eigen::Map<Vectors>(m_corners[e * N].data()));
    });
  }

  // out[v] += factor * (corners around v, summed in increasing element order).
  void sumCorners(std::span<Vec3d> out, double factor, const ThreadPool& pool) const {
    const std::size_t n = std::min(out.size(), pointCount());
    pool.parallelFor(n, kVertexGrain, [&](std::size_t begin, std::size_t end) {
      for (std::size_t v = begin; v < end; ++v) {
        const Index first = m_vertexOffsets[v], last = m_vertexOffsets[v + 1];
        if (first == last) continue;
        Vec3d sum = m_corners[m_vertexCorners[first]];
        for (Index c = first + 1; c < last; ++c) sum += m_corners[m_vertexCorners[c]];
        out[v] += factor * sum;
      }
    });
  }

  void addElementMatrix(MatrixAccumulator& matrix, std::size_t offset, std::size_t e, double factor,
                        const Matrix& K) const {
    std::array<std::size_t, N> rows;
    for (int i = 0; i < N; ++i) rows[i] = offset + 3 * std::size_t{m_elements[e][i]};
    matrix.addBlocks(rows, K, factor);
  }

  std::vector<Indices> m_elements;
  // Hexahedra: the distinct constants, m_constantIndex[e] the entry of element e. Tetrahedra:
  // one entry per element, in element order.
  std::vector<Element> m_constants;
  std::vector<std::uint32_t> m_constantIndex;  // (elements, hexahedra)
  std::vector<Vectors> m_restPositions;        // (elements, hexahedra) X (m)
  std::vector<Eigen::Matrix3d> m_rotations;
  std::vector<Vec3d> m_corners;           // (elements x N): element e, node i at e * N + i
  std::vector<Index> m_vertexOffsets{0};  // (points + 1) into m_vertexCorners
  std::vector<Index> m_vertexCorners;     // corners around each vertex, increasing
  std::vector<Matrix> m_matrices;         // (kMatrixBatch) scratch of addKToMatrix
  std::vector<char> m_degenerate;         // (constants) scratch of computeConstants
  // Tetrahedra: Ke = B(G_e)^T C B(G_e) with G_e = sqrt(E_e |V_e|) grad N and C = C(E = 1).
  std::vector<fem::TetrahedronRows> m_stiffnessFactors;  // (elements) G_e, by rows
  fem::Matrix6d m_unitElasticity = fem::Matrix6d::Zero();
  // Tetrahedra: K's blocks (Lame parameters of C(E = 1) when isotropic), whether they hold the
  // current rotations, and the products at this linearization point and the last one.
  fem::TetrahedronStiffnessBlocks m_stiffnessBlocks;
  std::optional<fem::LameParameters> m_unitLame;
  bool m_blocksCurrent = false;
  unsigned m_productsAtPoint = 0;
  unsigned m_productsAtLastPoint = 0;
  fem::VolumetricStiffness m_volumetric = fem::VolumetricStiffness::full;
};

}  // namespace stroma
