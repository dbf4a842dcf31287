// SPDX-License-Identifier: MIT
// The rotation of each node's neighbourhood from its rest shape, for a compliance computed at
// rest and turned with the body (PrecomputedConstraintCorrection). A kernel: no Data, no node.
//
// Node i's rotation R_i is the rotation of the best rigid fit of its one-ring (the nodes that
// share an edge with it) by shape matching (Mueller, Heidelberger, Teschner, Gross 2005,
// "Meshless deformations based on shape matching", eq. 7): the rotation of the polar
// decomposition of
//   A_i = sum_j (x_j - x_i) (X_j - X_i)^T,
// x current and X rest positions. A rigid motion of the ring gives its rotation exactly; a
// flat or inverted ring still gives a proper rotation (the SVD fallback of
// fem::computePolarRotation). A node without neighbours keeps R = I.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace stroma::lagrangian {

class NodeRotations {
 public:
  /// The one-rings of `nodeCount` nodes from the mesh's edges (node pairs; out-of-range ones
  /// are skipped).
  void build(std::size_t nodeCount, std::span<const std::array<std::uint32_t, 2>> edges);

  /// Every node's rotation from `rest` to `current` (nodeCount() points each). No allocation.
  void compute(std::span<const Eigen::Vector3d> rest, std::span<const Eigen::Vector3d> current);

  std::size_t nodeCount() const { return m_rotations.size(); }
  const Eigen::Matrix3d& operator[](std::size_t node) const { return m_rotations[node]; }

 private:
  std::vector<std::size_t>
      m_first;  // CSR: neighbours of i are m_neighbours[m_first[i], m_first[i+1])
  std::vector<std::uint32_t> m_neighbours;
  std::vector<Eigen::Matrix3d> m_rotations;
};

}  // namespace stroma::lagrangian
