// SPDX-License-Identifier: MIT
// SymmetricBlockMatrix: a copy of a symmetric sparse matrix of 3 x 3 blocks (one per pair of
// points), for the products of the multigrid cycles (CG smoothers: the matrices are symmetric
// anyway).
//
// Why: a smoothing product reads the whole matrix and does 2 flops per value, so its time is
// the bytes it reads. Eigen's compressed storage reads a value and a 4-byte row index per entry
// (12 bytes in double); 3 x 3 blocks read one index per 9 values (8.4 bytes per entry in
// double, 4.4 in single precision). Single precision is meant for the cycles that precondition
// an outer iteration in double (MultigridCycle::flexibleConjugateGradient): a cycle is then an
// approximate inverse anyway, and its products' relative error of about 1e-7 is far below what
// the cycle leaves.
//
// Layout: only the upper triangle of blocks (I <= J; the matrix is symmetric). Block column J
// holds the blocks (I, J) of its block rows I <= J in increasing order (the union of its 3
// columns' rows; the diagonal block last), each stored as its transpose S = B_IJ^T,
// column-major (9 values; 3 more at the end of the array, so that a 4-wide load of a block's
// last column stays inside it). A block that the source stores only in part (a fixed point's
// identity row, a diagonal mass) gets zeros in its other entries. Block columns follow Eigen's
// column-major order, so a refill reads and writes both arrays front to back (a block-row copy
// scatters its writes over the whole matrix). The product walks the block columns: y_J = sum
// over I <= J of S x_I (kept in registers: with AVX2, one 4-wide fused multiply-add per column
// of S) and, for I < J, y_I += S^T x_J (S transposed in registers, y_I's 3 values updated).
// Symmetry is the caller's premise, not checked: the assembled systems and Galerkin operators
// of the multigrid are symmetric to round-off.
#pragma once

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <cstdint>
#include <vector>

namespace stroma::multigrid {

class SymmetricBlockMatrix {
 public:
  enum class Precision { double_, single };

  /// Copies A (symmetric, 3n x 3n, column-major Eigen storage). With `samePattern` (the caller
  /// knows A has the pattern of the last call, e.g. from AssembledMatrix::patternRevision), only
  /// the values are copied; otherwise the pattern of blocks and the map from A's entries to
  /// block values are remade first.
  void assign(const Eigen::SparseMatrix<double>& A, Precision precision, bool samePattern);

  /// y = A x (computed as A^T x: A is symmetric).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;

  Eigen::Index rows() const { return 3 * Eigen::Index(m_blockColumnCount); }
  std::size_t blockCount() const { return m_blockRows.size(); }
  Precision precision() const { return m_precision; }

 private:
  void buildPattern(const Eigen::SparseMatrix<double>& A);
  template <class Scalar>
  /// Copies A's values into their slots; zeroes the array first when the pattern is new.
  void fill(const Eigen::SparseMatrix<double>& A, std::vector<Scalar>& values,
            bool newPattern) const;
  template <class Scalar>
  void multiplyWith(const std::vector<Scalar>& values, const Eigen::VectorXd& x,
                    Eigen::VectorXd& y) const;

  Precision m_precision = Precision::double_;
  std::size_t m_blockColumnCount = 0;
  std::vector<std::uint32_t> m_columnStarts;  ///< (block columns + 1) into m_blockRows
  std::vector<std::uint32_t> m_blockRows;     ///< block row of each block
  /// Where each entry of A goes among the block values (block * 9 + 3 * row + column, row and
  /// column within the block: the transposed block, column-major).
  std::vector<std::uint32_t> m_destination;
  std::vector<double> m_double;
  std::vector<float> m_single;
};

}  // namespace stroma::multigrid
