// SPDX-License-Identifier: MIT
#include "linalg/AssembledMatrix.h"

#include <algorithm>

namespace stroma {

void AssembledMatrix::begin(std::size_t n) {
  if (n != m_size) m_cachedEntries.clear();
  m_size = n;
  m_entries.clear();
  m_values.clear();
}

void AssembledMatrix::add(std::size_t row, std::size_t col, double value) {
  m_entries.push_back({static_cast<std::uint32_t>(row), static_cast<std::uint32_t>(col)});
  m_values.push_back(value);
}

void AssembledMatrix::finish() {
  if (m_entries == m_cachedEntries && m_matrix.rows() == static_cast<Eigen::Index>(m_size)) {
    // Same pattern as last time: refill in place.
    double* values = m_matrix.valuePtr();
    std::fill(values, values + m_matrix.nonZeros(), 0.0);
    for (std::size_t k = 0; k < m_values.size(); ++k) values[m_slots[k]] += m_values[k];
    return;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(m_entries.size());
  for (std::size_t k = 0; k < m_entries.size(); ++k)
    triplets.emplace_back(m_entries[k].row, m_entries[k].col, 0.0);
  const auto n = static_cast<Eigen::Index>(m_size);
  m_matrix.resize(n, n);
  m_matrix.setFromTriplets(triplets.begin(), triplets.end());
  m_matrix.makeCompressed();
  // The slot of each entry: binary search of its row in its column.
  m_slots.resize(m_entries.size());
  const auto* outer = m_matrix.outerIndexPtr();
  const auto* inner = m_matrix.innerIndexPtr();
  for (std::size_t k = 0; k < m_entries.size(); ++k) {
    const auto begin = inner + outer[m_entries[k].col];
    const auto end = inner + outer[m_entries[k].col + 1];
    m_slots[k] = std::lower_bound(begin, end, static_cast<int>(m_entries[k].row)) - inner;
  }
  double* values = m_matrix.valuePtr();
  for (std::size_t k = 0; k < m_values.size(); ++k) values[m_slots[k]] += m_values[k];
  m_cachedEntries = m_entries;
  ++m_patternRevision;
}

}  // namespace stroma
