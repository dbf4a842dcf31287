// SPDX-License-Identifier: MIT
#include "NodeRotations.h"

#include "SolidMechanics/kernels/RotationExtraction.h"

namespace stroma::lagrangian {

void NodeRotations::build(std::size_t nodeCount,
                          std::span<const std::array<std::uint32_t, 2>> edges) {
  // Counting sort of the two ends of each edge into compressed rows.
  m_first.assign(nodeCount + 1, 0);
  for (const auto& e : edges)
    if (e[0] < nodeCount && e[1] < nodeCount && e[0] != e[1]) {
      ++m_first[e[0] + 1];
      ++m_first[e[1] + 1];
    }
  for (std::size_t i = 0; i < nodeCount; ++i) m_first[i + 1] += m_first[i];
  m_neighbours.resize(m_first[nodeCount]);
  std::vector<std::size_t> next(m_first.begin(), m_first.end() - 1);
  for (const auto& e : edges)
    if (e[0] < nodeCount && e[1] < nodeCount && e[0] != e[1]) {
      m_neighbours[next[e[0]]++] = e[1];
      m_neighbours[next[e[1]]++] = e[0];
    }
  m_rotations.assign(nodeCount, Eigen::Matrix3d::Identity());
}

void NodeRotations::compute(std::span<const Eigen::Vector3d> rest,
                            std::span<const Eigen::Vector3d> current) {
  const std::size_t n = m_rotations.size();
  if (rest.size() < n || current.size() < n) return;
  for (std::size_t i = 0; i < n; ++i) {
    if (m_first[i] == m_first[i + 1]) continue;  // no neighbour: R stays I
    // A_i = sum_j (x_j - x_i)(X_j - X_i)^T (shape matching's A_pq).
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    for (std::size_t k = m_first[i]; k < m_first[i + 1]; ++k) {
      const std::uint32_t j = m_neighbours[k];
      A.noalias() += (current[j] - current[i]) * (rest[j] - rest[i]).transpose();
    }
    m_rotations[i] = fem::computePolarRotation(A);
  }
}

}  // namespace stroma::lagrangian
