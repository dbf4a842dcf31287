// SPDX-License-Identifier: MIT
#include "linalg/AssembledMatrix.h"

#include <algorithm>

namespace stroma {

namespace {
/// Blocks ahead whose matrix slots a refilling addBlock prefetches.
constexpr std::size_t kPrefetchDistance = 16;
}  // namespace

void AssembledMatrix::begin(std::size_t n) {
  m_refilling = m_built && m_matrix.rows() == static_cast<Eigen::Index>(n);
  if (!m_refilling) m_items.clear();
  m_size = n;
  m_cursor = 0;
  m_newItems.clear();
  m_values.clear();
  if (m_refilling) std::fill(m_matrix.valuePtr(), m_matrix.valuePtr() + m_matrix.nonZeros(), 0.0);
}

void AssembledMatrix::add(std::size_t row, std::size_t col, double value) {
  const Item item{static_cast<std::uint32_t>(row), static_cast<std::uint32_t>(col), 0};
  if (m_refilling) {
    if (m_cursor < m_items.size() && m_items[m_cursor] == item) {
      m_matrix.valuePtr()[m_slots[3 * m_cursor++]] += value;
      return;
    }
    startRecording();
  }
  m_newItems.push_back(item);
  m_values.push_back(value);
}

void AssembledMatrix::addBlock(std::size_t row, std::size_t col, const Eigen::Matrix3d& block) {
  const Item item{static_cast<std::uint32_t>(row), static_cast<std::uint32_t>(col), 1};
  if (m_refilling) {
    if (m_cursor < m_items.size() && m_items[m_cursor] == item) {
      double* values = m_matrix.valuePtr();
      prefetchSlots(m_cursor + kPrefetchDistance);
      const int* slots = &m_slots[3 * m_cursor++];
      for (int j = 0; j < 3; ++j) {
        double* column = values + slots[j];
        column[0] += block(0, j);
        column[1] += block(1, j);
        column[2] += block(2, j);
      }
      return;
    }
    startRecording();
  }
  m_newItems.push_back(item);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m_values.push_back(block(i, j));
}

void AssembledMatrix::addBlocks(std::span<const std::size_t> offsets,
                                const Eigen::Ref<const Eigen::MatrixXd>& M, double factor) {
  const std::size_t n = offsets.size();
  const auto sameAsRecorded = [&] {
    if (!m_refilling || m_cursor + n * n > m_items.size()) return false;
    const Item* item = &m_items[m_cursor];
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j, ++item)
        if (item->row != offsets[i] || item->col != offsets[j] || !item->block) return false;
    return true;
  };
  if (!sameAsRecorded()) {
    MatrixAccumulator::addBlocks(offsets, M, factor);
    return;
  }
  // The sums of addBlock(offsets[i], offsets[j], factor * block), in the same order.
  double* values = m_matrix.valuePtr();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      prefetchSlots(m_cursor + kPrefetchDistance);
      const int* slots = &m_slots[3 * m_cursor++];
      const auto block = M.block<3, 3>(3 * static_cast<Eigen::Index>(i),
                                       3 * static_cast<Eigen::Index>(j));
      for (int c = 0; c < 3; ++c) {
        double* column = values + slots[c];
        column[0] += factor * block(0, c);
        column[1] += factor * block(1, c);
        column[2] += factor * block(2, c);
      }
    }
  }
}

void AssembledMatrix::prefetchSlots(std::size_t item) const {
  // The slots of a later block are known: asking for them now makes the cache misses of a
  // matrix larger than the cache overlap instead of following one another (assembly of 32^3
  // hexahedra: 61 -> 51 ms per refill).
  if (item >= m_items.size()) return;
  const double* values = m_matrix.valuePtr();
  const int* slots = &m_slots[3 * item];
  for (int c = 0; c < 3; ++c) __builtin_prefetch(values + slots[c], 1);
}

void AssembledMatrix::startRecording() {
  // The items before the cursor repeated the recorded sequence: their sum is in m_matrix. Keep
  // them in the new sequence (with zero values) and carry the sum over into the new pattern.
  m_refilling = false;
  m_newItems.assign(m_items.begin(), m_items.begin() + static_cast<std::ptrdiff_t>(m_cursor));
  std::size_t count = 0;
  for (const Item& item : m_newItems) count += item.block ? 9 : 1;
  m_values.assign(count, 0.0);
  if (m_cursor > 0) m_carried = m_matrix;
}

void AssembledMatrix::finish() {
  if (m_refilling) {
    if (m_cursor == m_items.size()) return;  // the same sequence: the values are in place
    startRecording();                        // it ended early: a new, smaller pattern
  }
  buildPattern();
}

namespace {
/// Index in `matrix`'s values of (row, col), which must be in its pattern.
int slotOf(const Eigen::SparseMatrix<double>& matrix, std::uint32_t row, std::uint32_t col) {
  const int* inner = matrix.innerIndexPtr();
  const int* begin = inner + matrix.outerIndexPtr()[col];
  const int* end = inner + matrix.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, static_cast<int>(row)) - inner);
}
}  // namespace

void AssembledMatrix::buildPattern() {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(m_values.size());
  for (const Item& item : m_newItems) {
    const int size = item.block ? 3 : 1;
    for (int i = 0; i < size; ++i)
      for (int j = 0; j < size; ++j) triplets.emplace_back(item.row + i, item.col + j, 0.0);
  }
  const auto n = static_cast<Eigen::Index>(m_size);
  m_matrix.resize(n, n);
  m_matrix.setFromTriplets(triplets.begin(), triplets.end());
  m_matrix.makeCompressed();
  triplets = {};

  m_slots.assign(3 * m_newItems.size(), 0);
  double* values = m_matrix.valuePtr();
  const double* added = m_values.data();
  for (std::size_t k = 0; k < m_newItems.size(); ++k) {
    const Item& item = m_newItems[k];
    if (!item.block) {
      m_slots[3 * k] = slotOf(m_matrix, item.row, item.col);
      values[m_slots[3 * k]] += *added++;
      continue;
    }
    for (std::uint32_t j = 0; j < 3; ++j) {
      const int slot = slotOf(m_matrix, item.row, item.col + j);
      m_slots[3 * k + j] = slot;
      for (int i = 0; i < 3; ++i) values[slot + i] += added[3 * i + j];
    }
    added += 9;
  }
  // Sums added before the sequence changed (their items are in the new sequence).
  for (Eigen::Index c = 0; c < m_carried.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator e(m_carried, c); e; ++e)
      if (e.value() != 0)
        values[slotOf(m_matrix, static_cast<std::uint32_t>(e.row()),
                      static_cast<std::uint32_t>(e.col()))] += e.value();
  m_carried = Eigen::SparseMatrix<double>();
  m_items.swap(m_newItems);
  m_newItems = {};
  m_values = {};
  m_built = true;
  ++m_patternRevision;
}

}  // namespace stroma
