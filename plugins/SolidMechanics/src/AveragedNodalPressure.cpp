// SPDX-License-Identifier: MIT
#include "AveragedNodalPressure.h"

#include <algorithm>

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

void AveragedNodalPressure::setup(Elements& elements, std::span<const double> youngModulus,
                                  double poissonRatio, const ThreadPool& pool) {
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
  // V_a and kappa_a V_a, by the elements' deterministic vertex sums.
  m_nodal.assign(points, Vec3d::Zero());
  elements.accumulate(m_nodal, 1.0, pool,
                      [this](std::size_t e, Eigen::Map<fem::TetrahedronVectors> corner) {
                        const double share = m_volume[e] / 4;
                        corner.row(0).setConstant(share);
                        corner.row(1).setConstant(share * m_bulkModulus[e]);
                        corner.row(2).setZero();
                      });
  m_nodalVolume.resize(points);
  m_nodalBulkModulus.resize(points);
  for (std::size_t a = 0; a < points; ++a) {
    m_nodalVolume[a] = m_nodal[a].x();
    m_nodalBulkModulus[a] = m_nodal[a].x() > 0 ? m_nodal[a].y() / m_nodal[a].x() : 0.0;
  }
  m_pressure.assign(points, 0.0);
  m_dPressure.assign(points, 0.0);
  // Vertex -> tetrahedra, increasing (a counting sort), for the assembled matrix.
  m_vertexOffsets.assign(points + 1, 0);
  for (const auto& nodes : elements.elements())
    for (Index v : nodes) ++m_vertexOffsets[v + 1];
  for (std::size_t a = 0; a < points; ++a) m_vertexOffsets[a + 1] += m_vertexOffsets[a];
  m_vertexElements.resize(m_vertexOffsets[points]);
  std::vector<Index> next(m_vertexOffsets.begin(), m_vertexOffsets.end() - 1);
  for (std::size_t e = 0; e < count; ++e)
    for (Index v : elements.elements()[e]) m_vertexElements[next[v]++] = static_cast<Index>(e);
}

template <class Divergence>
void AveragedNodalPressure::averagePressure(Elements& elements, std::span<double> pressure,
                                            const ThreadPool& pool, Divergence&& divergence) {
  std::fill(m_nodal.begin(), m_nodal.end(), Vec3d::Zero());
  elements.accumulate(
      m_nodal, 1.0, pool,
      [this, &divergence](std::size_t e, Eigen::Map<fem::TetrahedronVectors> corner) {
        corner.setZero();
        corner.row(0).setConstant(m_volume[e] / 4 * divergence(e));
      });
  // p_a = kappa_a theta_a = kappa_a (sum (V_e / 4) d_e) / V_a.
  for (std::size_t a = 0; a < pressure.size(); ++a)
    pressure[a] =
        m_nodalVolume[a] > 0 ? m_nodalBulkModulus[a] * m_nodal[a].x() / m_nodalVolume[a] : 0.0;
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
        corner.noalias() = (-m_volume[e] * meanPressure) * elements.rotations()[e] * m_gradients[e];
      });
}

void AveragedNodalPressure::addForce(Elements& elements, std::span<const Vec3d> x,
                                     std::span<Vec3d> f, const ThreadPool& pool) {
  averagePressure(elements, m_pressure, pool, [&](std::size_t e) {
    return fem::computeCorotatedDivergence(m_gradients[e], elements.rotations()[e],
                                           elements.gather(x, e),
                                           elements.constants()[e].restPositions);
  });
  scatterPressure(elements, m_pressure, f, 1.0, pool);
}

void AveragedNodalPressure::addDForce(Elements& elements, std::span<const Vec3d> dx,
                                      std::span<Vec3d> df, double kFactor, const ThreadPool& pool) {
  averagePressure(elements, m_dPressure, pool, [&](std::size_t e) {
    return fem::computeCorotatedDivergence(m_gradients[e], elements.rotations()[e],
                                           elements.gather(dx, e), fem::TetrahedronVectors::Zero());
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
      const fem::TetrahedronVectors w =
          (m_volume[e] / 4) * elements.rotations()[e] * m_gradients[e];
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
