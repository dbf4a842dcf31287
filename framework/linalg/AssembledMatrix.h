// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Sparse>
#include <cstdint>
#include <span>
#include <vector>

namespace stroma {

/// Where components add their matrix entries: global row and column, value. Entries at the
/// same place add up.
class MatrixAccumulator {
 public:
  virtual ~MatrixAccumulator() = default;
  virtual void add(std::size_t row, std::size_t col, double value) = 0;
  /// A 3x3 block at (row, col). Virtual so that an accumulator can take the 9 values in one
  /// call (AssembledMatrix writes them straight into their 3 column runs).
  virtual void addBlock(std::size_t row, std::size_t col, const Eigen::Matrix3d& block) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add(row + i, col + j, block(i, j));
  }
  /// factor * M for a matrix M of n x n 3x3 blocks (an element's, n = offsets.size()), block
  /// (i, j) at row offsets[i] and column offsets[j]: the calls addBlock(offsets[i],
  /// offsets[j], factor * block(i, j)) for i, then j, increasing, which is what this default
  /// does. Virtual so that an accumulator can take an element in one call (AssembledMatrix
  /// checks its 64 blocks against the recorded sequence at once and adds them in place).
  virtual void addBlocks(std::span<const std::size_t> offsets,
                         const Eigen::Ref<const Eigen::MatrixXd>& M, double factor) {
    const auto n = static_cast<Eigen::Index>(offsets.size());
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j)
        addBlock(offsets[i], offsets[j], factor * M.block<3, 3>(3 * i, 3 * j));
  }
};

/// A sparse matrix assembled each step by the same components in the same order. The first
/// assembly records the sequence of calls (scalar entries and 3x3 blocks) and builds the
/// pattern; later ones, while the calls repeat that sequence, add each value straight into its
/// slot of the matrix (a block: 3 slots, one per column, its 3 rows being consecutive there),
/// with no sorting, no allocation and no copy of the values, so that factorizations can reuse
/// their symbolic analysis (patternRevision() is unchanged). A call that departs from the
/// recorded sequence (or an assembly that ends early) switches to recording: the values already
/// added are carried over into the new pattern, so the result is the same either way.
class AssembledMatrix final : public MatrixAccumulator {
 public:
  /// Starts an assembly of an n x n matrix.
  void begin(std::size_t n);
  void add(std::size_t row, std::size_t col, double value) override;
  void addBlock(std::size_t row, std::size_t col, const Eigen::Matrix3d& block) override;
  /// While refilling and the element's blocks are the next ones of the recorded sequence: adds
  /// them in place, the sums of the default to round-off (factor * value + sum may be one
  /// fused multiply-add); otherwise the default (block by block).
  void addBlocks(std::span<const std::size_t> offsets, const Eigen::Ref<const Eigen::MatrixXd>& M,
                 double factor) override;
  /// Ends the assembly; the matrix is then ready.
  void finish();

  const Eigen::SparseMatrix<double>& matrix() const { return m_matrix; }
  /// Changes whenever the sparsity pattern changed.
  std::uint64_t patternRevision() const { return m_patternRevision; }

 private:
  struct Item {
    std::uint32_t row, col;
    std::uint32_t block;  ///< 1 for a 3x3 block at (row, col), 0 for one entry
    bool operator==(const Item&) const = default;
  };
  /// Prefetches the matrix slots of the recorded item `item` when there is one.
  void prefetchSlots(std::size_t item) const;
  /// The call departs from the recorded sequence at m_cursor: record from now on.
  void startRecording();
  void buildPattern();

  std::size_t m_size = 0;
  bool m_built = false;                   ///< m_items and m_slots describe m_matrix
  bool m_refilling = false;               ///< adding into the slots of the recorded sequence
  std::size_t m_cursor = 0;               ///< next item of the recorded sequence
  std::vector<Item> m_items;              ///< the recorded sequence
  std::vector<int> m_slots;               ///< 3 per item: value index of (row, col + j), j = 0..2
  std::vector<Item> m_newItems;           ///< recording: the sequence of this assembly
  std::vector<double> m_values;           ///< recording: 1 or 9 (row-major) values per new item
  Eigen::SparseMatrix<double> m_carried;  ///< values added before the sequence changed
  Eigen::SparseMatrix<double> m_matrix;
  std::uint64_t m_patternRevision = 0;
};

}  // namespace stroma
