// SPDX-License-Identifier: MIT
// The corotational stiffness of a tetrahedral mesh of one isotropic material,
//
//   K = sum_e R_e Ke_e R_e^T   (N/m; df = -K dx),
//
// kept as the 3 x 3 blocks K_ij of the vertex pairs that share a tetrahedron (a block-sparse
// matrix, every block row whole), refilled at each linearization point. An iterative solve
// applies K many times at one point (a CG step of SOFA's liver: 18 products per refill); a
// block row product reads about 11 blocks per vertex, where the element loop recomputes the
// rotations and the strain of every element for every product.
//
// Refill without Ke. For an isotropic C with Lame parameters (lambda, mu), the block (a, b) of
// Ke = B(G)^T C B(G), G = sqrt(E |V|) grad N (CorotationalTetrahedron.h's stiffness factor),
// is lambda g_a g_b^T + mu g_b g_a^T + mu (g_a . g_b) I (LinearTetrahedron.h). Isotropy makes
// R Ke R^T the Ke of the rotated gradients R g, so a block of K is, with
// P = sum over its elements of (R g_a)(R g_b)^T,
//
//   K_ij = lambda P + mu P^T + mu tr(P) I,
//
// 9 multiply-adds per element and node pair, after one rotation of each element's gradients.
// The blocks equal those of computeStiffness (R Ke R^T) to round-off.
//
// Determinism. Each block sums its elements in increasing element order and each product row
// sums its blocks in column order, whatever the split of the rows: the same numbers for any
// thread count. The caller runs the steps over ranges (its thread pool), in the order
// rotateFactors, fillUpperBlocks, fillLowerBlocks; none of them allocates.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "SolidMechanics/kernels/CorotationalTetrahedron.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"

namespace stroma::fem {

/// The Lame parameters of a Voigt elasticity matrix of the isotropic form of
/// IsotropicMaterial.h (its deviatoric part, VolumetricSplit.h, has that form too):
/// lambda = C(0, 1), mu = C(3, 3); nullopt when C differs from that form by more than 1e-12 of
/// its largest entry.
std::optional<LameParameters> findLameParameters(const Matrix6d& C);

class TetrahedronStiffnessBlocks {
 public:
  using Tetrahedron = std::array<std::uint32_t, 4>;

  /// The blocks of the vertex pairs of `elements` (vertex indices < pointCount) and, for each
  /// block, its elements and node pairs. Allocates; call when the mesh changes.
  void setPattern(std::span<const Tetrahedron> elements, std::size_t pointCount);

  std::size_t rowCount() const { return m_rowStart.size() - 1; }
  std::size_t elementCount() const { return m_rotatedFactors.size(); }
  std::size_t blockCount() const { return m_columns.size(); }

  /// Refill step 1, elements [begin, end): R_e G_e from the element rotations and stiffness
  /// factors (computeStiffnessFactor, by rows), both in element order.
  void rotateFactors(std::span<const Eigen::Matrix3d> rotations,
                     std::span<const TetrahedronRows> factors, std::size_t begin, std::size_t end);
  /// Refill step 2, rows [begin, end): the blocks K_ij with j >= i, for C(E = 1) of Lame
  /// parameters `lame` (the factors carry E).
  void fillUpperBlocks(const LameParameters& lame, std::size_t begin, std::size_t end);
  /// Refill step 3, rows [begin, end): K_ij = K_ji^T for j < i (after step 2 on every row).
  void fillLowerBlocks(std::size_t begin, std::size_t end);

  /// out_i += factor sum_j K_ij v_j for the rows i in [begin, end).
  void multiply(std::span<const Eigen::Vector3d> v, std::span<Eigen::Vector3d> out, double factor,
                std::size_t begin, std::size_t end) const;

  /// The block K_ij (N/m); zero when i and j share no tetrahedron (for tests).
  Eigen::Matrix3d block(std::size_t i, std::size_t j) const;

 private:
  std::vector<std::uint32_t> m_rowStart{0};  // (rows + 1) into the blocks
  std::vector<std::uint32_t> m_columns;      // (blocks) column of each block, increasing per row
  // K_ij with a zero fourth row: a column fills one AVX register, a block row product is 3
  // multiply-adds of 4 numbers per block (1.35 times faster than with Matrix3d, on the liver).
  using Block = Eigen::Matrix<double, 4, 3>;
  std::vector<Block> m_blocks;  // (blocks)
  // Upper blocks (j >= i): their contributions e * 16 + a * 4 + b (element e, nodes a and b),
  // in increasing element order. Lower blocks: m_mirror, the index of K_ji.
  std::vector<std::uint32_t> m_contributionStart;  // (blocks + 1)
  std::vector<std::uint32_t> m_contributions;
  std::vector<std::uint32_t> m_mirror;               // (blocks)
  std::vector<TetrahedronVectors> m_rotatedFactors;  // (elements) column a = R g_a
};

}  // namespace stroma::fem
