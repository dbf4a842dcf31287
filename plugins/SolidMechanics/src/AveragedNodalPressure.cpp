// SPDX-License-Identifier: MIT
#include "AveragedNodalPressure.h"

#include <algorithm>
#include <cmath>

#include "SolidMechanics/kernels/VolumetricSplit.h"

namespace stroma {

namespace {

/// Rest gradients g_i = grad N_i (column i, 1/m): rows of Dm^-1 for i = 1..3, g_0 = -(sum).
fem::TetrahedronVectors restGradients(const fem::CorotationalTetrahedron& element) {
  fem::TetrahedronVectors g;
  g.rightCols<3>() = element.restEdgesInverse.transpose();
  g.col(0) = -g.rightCols<3>().rowwise().sum();
  return g;
}

}  // namespace

void AveragedNodalPressure::setup(const Elements& elements, std::span<const double> youngModulus,
                                  double poissonRatio) {
  const std::size_t count = elements.size(), points = elements.pointCount();
  m_gradients.resize(count);
  m_volume.resize(count);
  m_bulkModulus.resize(count);
  for (std::size_t e = 0; e < count; ++e) {
    const fem::CorotationalTetrahedron& element = elements.constants()[e];
    m_gradients[e] = restGradients(element);
    // A degenerate element has zero constants (restVolume 0): it weighs nothing.
    m_volume[e] = std::abs(element.restVolume);
    m_bulkModulus[e] = fem::computeBulkModulus(
        fem::computeLameParameters(youngModulus[youngModulus.size() == 1 ? 0 : e], poissonRatio));
  }
  // Vertex -> tetrahedra, increasing (a counting sort): the order of every vertex sum.
  m_vertexOffsets.assign(points + 1, 0);
  for (const auto& nodes : elements.elements())
    for (Index v : nodes) ++m_vertexOffsets[v + 1];
  for (std::size_t a = 0; a < points; ++a) m_vertexOffsets[a + 1] += m_vertexOffsets[a];
  m_vertexElements.resize(m_vertexOffsets[points]);
  std::vector<Index> next(m_vertexOffsets.begin(), m_vertexOffsets.end() - 1);
  for (std::size_t e = 0; e < count; ++e)
    for (Index v : elements.elements()[e]) m_vertexElements[next[v]++] = static_cast<Index>(e);
  // V_a = sum V_e / 4 and kappa_a = sum (V_e / 4) kappa_e / V_a over the tetrahedra around a.
  m_nodalVolume.assign(points, 0.0);
  m_nodalBulkModulus.assign(points, 0.0);
  for (std::size_t a = 0; a < points; ++a) {
    double volume = 0, stiffness = 0;
    for (Index k = m_vertexOffsets[a]; k < m_vertexOffsets[a + 1]; ++k) {
      const Index e = m_vertexElements[k];
      volume += m_volume[e] / 4;
      stiffness += m_volume[e] / 4 * m_bulkModulus[e];
    }
    m_nodalVolume[a] = volume;
    m_nodalBulkModulus[a] = volume > 0 ? stiffness / volume : 0.0;
  }
  // The rotated gradients of the current rotations (those of init until the first addForce).
  m_rotatedGradients.resize(count);
  for (std::size_t e = 0; e < count; ++e)
    m_rotatedGradients[e] = elements.rotations()[e] * m_gradients[e];
  m_share.assign(count, 0.0);
  m_pressure.assign(points, 0.0);
  m_dPressure.assign(points, 0.0);
}

template <class Divergence>
void AveragedNodalPressure::averagePressure(std::span<double> pressure, const ThreadPool& pool,
                                            Divergence&& divergence) {
  // (V_e / 4) d_e per tetrahedron, then p_a = kappa_a theta_a = kappa_a (sum (V_e / 4) d_e) / V_a
  // summed in increasing element order: the same bits for any thread count.
  pool.parallelFor(m_share.size(), Elements::kProductGrain,
                   [this, &divergence](std::size_t begin, std::size_t end) {
                     for (std::size_t e = begin; e < end; ++e)
                       m_share[e] = m_volume[e] / 4 * divergence(e);
                   });
  pool.parallelFor(
      pressure.size(), Elements::kVertexGrain,
      [this, &pressure](std::size_t begin, std::size_t end) {
        for (std::size_t a = begin; a < end; ++a) {
          double sum = 0;
          for (Index k = m_vertexOffsets[a]; k < m_vertexOffsets[a + 1]; ++k)
            sum += m_share[m_vertexElements[k]];
          pressure[a] = m_nodalVolume[a] > 0 ? m_nodalBulkModulus[a] * sum / m_nodalVolume[a] : 0.0;
        }
      });
}

void AveragedNodalPressure::scatterPressure(Elements& elements, std::span<const double> pressure,
                                            std::span<Vec3d> out, double factor,
                                            const ThreadPool& pool) {
  elements.accumulate(
      out, factor, pool,
      [this, &elements, pressure](std::size_t e, Eigen::Map<fem::TetrahedronVectors> corner) {
        const auto& nodes = elements.elements()[e];
        const double meanPressure =
            (pressure[nodes[0]] + pressure[nodes[1]] + pressure[nodes[2]] + pressure[nodes[3]]) / 4;
        corner.noalias() = (-m_volume[e] * meanPressure) * m_rotatedGradients[e];
      });
}

void AveragedNodalPressure::addForce(Elements& elements, std::span<const Vec3d> x,
                                     std::span<Vec3d> f, const ThreadPool& pool) {
  averagePressure(m_pressure, pool, [&](std::size_t e) {
    const Eigen::Matrix3d& R = elements.rotations()[e];
    m_rotatedGradients[e].noalias() = R * m_gradients[e];
    return fem::computeCorotatedDivergence(m_gradients[e], R, elements.gather(x, e),
                                           elements.constants()[e].restPositions);
  });
  scatterPressure(elements, m_pressure, f, 1.0, pool);
}

void AveragedNodalPressure::addDForce(Elements& elements, std::span<const Vec3d> dx,
                                      std::span<Vec3d> df, double kFactor, const ThreadPool& pool) {
  // d_e = sum_i g_i . (R_e^T dx_i) = sum_i (R_e g_i) . dx_i, relative to node 0 as the force
  // (the g_i sum to zero).
  averagePressure(m_dPressure, pool, [&](std::size_t e) {
    const auto& nodes = elements.elements()[e];
    const fem::TetrahedronVectors& G = m_rotatedGradients[e];
    const Vec3d& dx0 = dx[nodes[0]];
    return G.col(1).dot(dx[nodes[1]] - dx0) + G.col(2).dot(dx[nodes[2]] - dx0) +
           G.col(3).dot(dx[nodes[3]] - dx0);
  });
  scatterPressure(elements, m_dPressure, df, kFactor, pool);
}

void AveragedNodalPressure::addKToMatrix(const Elements& elements, MatrixAccumulator& matrix,
                                         std::size_t offset, double kFactor) {
  if (kFactor == 0) return;
  for (std::size_t a = 0; a + 1 < m_vertexOffsets.size(); ++a) {
    if (!(m_nodalVolume[a] > 0)) continue;
    // w_a over the vertices of the tetrahedra around a, in order of first appearance.
    m_ringNodes.clear();
    m_ringWeights.clear();
    for (Index k = m_vertexOffsets[a]; k < m_vertexOffsets[a + 1]; ++k) {
      const Index e = m_vertexElements[k];
      const fem::TetrahedronVectors w = (m_volume[e] / 4) * m_rotatedGradients[e];
      for (int i = 0; i < 4; ++i) {
        const Index node = elements.elements()[e][i];
        const auto found = std::find(m_ringNodes.begin(), m_ringNodes.end(), node);
        if (found == m_ringNodes.end()) {
          m_ringNodes.push_back(node);
          m_ringWeights.push_back(w.col(i));
        } else {
          m_ringWeights[found - m_ringNodes.begin()] += w.col(i);
        }
      }
    }
    const double scale = -kFactor * m_nodalBulkModulus[a] / m_nodalVolume[a];
    for (std::size_t i = 0; i < m_ringNodes.size(); ++i)
      for (std::size_t j = 0; j < m_ringNodes.size(); ++j)
        matrix.addBlock(offset + 3 * std::size_t{m_ringNodes[i]},
                        offset + 3 * std::size_t{m_ringNodes[j]},
                        scale * m_ringWeights[i] * m_ringWeights[j].transpose());
  }
}

double AveragedNodalPressure::energy(const Elements& elements, fem::RotationMethod method,
                                     std::span<const Vec3d> x) const {
  std::vector<double> sums(m_nodalVolume.size(), 0.0);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const fem::TetrahedronVectors xe = elements.gather(x, e);
    const fem::CorotationalTetrahedron& element = elements.constants()[e];
    const double share =
        m_volume[e] / 4 *
        fem::computeCorotatedDivergence(m_gradients[e], fem::computeRotation(method, element, xe),
                                        xe, element.restPositions);
    for (Index v : elements.elements()[e]) sums[v] += share;
  }
  // 1/2 kappa_a V_a theta_a^2 with theta_a = sums_a / V_a.
  double total = 0;
  for (std::size_t a = 0; a < sums.size(); ++a)
    if (m_nodalVolume[a] > 0)
      total += 0.5 * m_nodalBulkModulus[a] * sums[a] * sums[a] / m_nodalVolume[a];
  return total;
}

}  // namespace stroma
