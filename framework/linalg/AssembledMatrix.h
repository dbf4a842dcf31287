// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Sparse>
#include <cstdint>
#include <vector>

namespace stroma {

/// Where components add their matrix entries: global row and column, value. Entries at the
/// same place add up.
class MatrixAccumulator {
 public:
  virtual ~MatrixAccumulator() = default;
  virtual void add(std::size_t row, std::size_t col, double value) = 0;
  /// A 3x3 block at (row, col).
  void addBlock(std::size_t row, std::size_t col, const Eigen::Matrix3d& block) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add(row + i, col + j, block(i, j));
  }
};

/// A sparse matrix assembled each step by the same components in the same order. The first
/// assembly builds the pattern; later ones, when the sequence of (row, col) is unchanged, refill
/// the values in place through a direct index map (no sorting, no allocation), so that
/// factorizations can reuse their symbolic analysis (patternRevision() is unchanged).
class AssembledMatrix final : public MatrixAccumulator {
 public:
  /// Starts an assembly of an n x n matrix.
  void begin(std::size_t n);
  void add(std::size_t row, std::size_t col, double value) override;
  /// Ends the assembly; the matrix is then ready.
  void finish();

  const Eigen::SparseMatrix<double>& matrix() const { return m_matrix; }
  /// Changes whenever the sparsity pattern changed.
  std::uint64_t patternRevision() const { return m_patternRevision; }

 private:
  struct Entry {
    std::uint32_t row, col;
    bool operator==(const Entry&) const = default;
  };
  std::size_t m_size = 0;
  std::vector<Entry> m_entries;
  std::vector<double> m_values;
  std::vector<Entry> m_cachedEntries;
  std::vector<std::int64_t> m_slots;  ///< entry k -> index in m_matrix.valuePtr()
  Eigen::SparseMatrix<double> m_matrix;
  std::uint64_t m_patternRevision = 0;
};

}  // namespace stroma
