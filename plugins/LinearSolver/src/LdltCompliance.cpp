// SPDX-License-Identifier: MIT
#include "LdltCompliance.h"

#include <algorithm>
#include <cmath>

namespace stroma {

namespace {

using Lanes = Eigen::Matrix<double, LdltCompliance::kLanes, 1>;

// Rows r and q of J have the same columns (the normal and tangent rows of one contact do).
bool samePattern(const LdltCompliance::RowMatrix& J, int r, int q) {
  const int* start = J.outerIndexPtr();
  const int* columns = J.innerIndexPtr();
  return start[r + 1] - start[r] == start[q + 1] - start[q] &&
         std::equal(columns + start[r], columns + start[r + 1], columns + start[q]);
}

}  // namespace

void LdltCompliance::setFactor(const Factor& L) {
  const auto n = static_cast<std::size_t>(L.cols());
  m_parent.assign(n, -1);
  const int* start = L.outerIndexPtr();
  const int* rows = L.innerIndexPtr();
  for (std::size_t j = 0; j < n; ++j)
    if (start[j] < start[j + 1]) m_parent[j] = rows[start[j]];
  m_mark.assign(n, -1);
  m_slot.assign(n, -1);
  m_column.assign(n, -1);
  m_work.assign(n * kLanes, 0.0);
  m_path.resize(n);
  m_stack.resize(n);
}

bool LdltCompliance::add(const Factor& L, const Eigen::VectorXd& D,
                         const Eigen::VectorXi& permutation, const RowMatrix& J, double factor,
                         Eigen::MatrixXd& W) {
  const auto n = static_cast<int>(m_parent.size());
  if (L.cols() != n || J.cols() != n || D.size() != n) return false;
  const int m = static_cast<int>(J.rows());
  if (m == 0) return true;

  // The columns J touches (explicit zeros left out: a contact on a triangle's vertex carries
  // the other two vertices with weight 0). Fewer columns than rows (three rows per contact):
  // the block X = E^T A^-1 E of those columns, then W += J_c X J_c^T; otherwise J A^-1 J^T
  // directly, one right-hand side per row.
  m_columns.clear();
  for (int p = 0; p < J.nonZeros(); ++p) {
    if (J.valuePtr()[p] == 0) continue;
    int& c = m_column[static_cast<std::size_t>(J.innerIndexPtr()[p])];
    if (c < 0) {
      c = static_cast<int>(m_columns.size());
      m_columns.push_back(J.innerIndexPtr()[p]);
    }
  }
  const bool byColumns = m_columns.size() < static_cast<std::size_t>(m);
  m_rhsStart.clear();
  m_rhsIndex.clear();
  m_rhsValue.clear();
  m_groupStart.clear();
  if (byColumns) {
    // Unit right-hand sides, grouped by runs of consecutive columns (a vertex's dofs).
    std::sort(m_columns.begin(), m_columns.end());
    for (std::size_t c = 0; c < m_columns.size(); ++c) {
      m_column[static_cast<std::size_t>(m_columns[c])] = static_cast<int>(c);
      const bool run = c > 0 && m_columns[c] == m_columns[c - 1] + 1 &&
                       static_cast<int>(c) - m_groupStart.back() < kLanes;
      if (!run) m_groupStart.push_back(static_cast<int>(c));
      m_rhsStart.push_back(static_cast<int>(m_rhsIndex.size()));
      m_rhsIndex.push_back(m_columns[c]);
      m_rhsValue.push_back(1.0);
    }
  } else {
    // The rows of J, grouped by runs of rows with the same columns (a contact's three).
    const int* start = J.outerIndexPtr();
    for (int r = 0; r < m; ++r) {
      if (r == 0 || !samePattern(J, r, r - 1) || r - m_groupStart.back() == kLanes)
        m_groupStart.push_back(r);
      m_rhsStart.push_back(static_cast<int>(m_rhsIndex.size()));
      for (int p = start[r]; p < start[r + 1]; ++p)
        if (J.valuePtr()[p] != 0) {
          m_rhsIndex.push_back(J.innerIndexPtr()[p]);
          m_rhsValue.push_back(J.valuePtr()[p]);
        }
    }
  }
  m_rhsStart.push_back(static_cast<int>(m_rhsIndex.size()));
  m_groupStart.push_back(static_cast<int>(m_rhsStart.size()) - 1);

  const bool positive = solve(L, D, permutation);
  const Block Y = gatherBlock();
  if (positive && !byColumns) {
    // W += factor Y^T Y (lower triangle, then mirrored).
    W.selfadjointView<Eigen::Lower>().rankUpdate(Y.transpose(), factor);
    for (Eigen::Index c = 1; c < m; ++c)
      for (Eigen::Index r = 0; r < c; ++r) W(r, c) = W(c, r);
  } else if (positive) {
    // X = Y^T Y, then W += factor J_c X J_c^T with J_c the columns J touches.
    const auto c = static_cast<Eigen::Index>(m_columns.size());
    m_X.setZero(c, c);
    m_X.selfadjointView<Eigen::Lower>().rankUpdate(Y.transpose());
    m_X.triangularView<Eigen::StrictlyUpper>() = m_X.transpose();
    m_triplets.clear();
    for (int r = 0; r < m; ++r)
      for (RowMatrix::InnerIterator e(J, r); e; ++e)
        if (e.value() != 0)
          m_triplets.emplace_back(r, m_column[static_cast<std::size_t>(e.col())], e.value());
    m_Jc.resize(m, c);
    m_Jc.setFromTriplets(m_triplets.begin(), m_triplets.end());
    m_XJt.noalias() = m_X * m_Jc.transpose();
    W.noalias() += factor * (m_Jc * m_XJt);
  }
  for (int col : m_columns) m_column[static_cast<std::size_t>(col)] = -1;
  return positive;
}

// Forward substitution of each group of right-hand sides on the columns of L their non-zeros
// reach (one pass over those columns for the group, kLanes values per dof); keeps
// D^-1/2 L^-1 P b of each on the reached dofs.
bool LdltCompliance::solve(const Factor& L, const Eigen::VectorXd& D,
                           const Eigen::VectorXi& permutation) {
  const auto n = static_cast<int>(m_parent.size());
  const int* start = L.outerIndexPtr();
  const int* rows = L.innerIndexPtr();
  const double* values = L.valuePtr();
  double* work = m_work.data();
  const auto rhsCount = static_cast<int>(m_rhsStart.size()) - 1;
  m_reached.clear();
  m_reachStart.assign(static_cast<std::size_t>(rhsCount) + 1, 0);
  m_reachIndex.clear();
  m_reachValue.clear();
  bool positive = true;
  for (std::size_t group = 0; group + 1 < m_groupStart.size(); ++group) {
    const int first = m_groupStart[group], lanes = m_groupStart[group + 1] - first;
    // The reach, in topological order without sorting: each path from a non-zero up to the
    // first column already reached goes in front of the earlier paths (its columns are
    // descendants of theirs, never ancestors; Davis 2006, cs_ereach).
    int top = n;
    for (int g = 0; g < lanes; ++g)
      for (int q = m_rhsStart[static_cast<std::size_t>(first + g)];
           q < m_rhsStart[static_cast<std::size_t>(first + g) + 1]; ++q) {
        const int column = m_rhsIndex[static_cast<std::size_t>(q)];
        const int k = permutation.size() ? permutation[column] : column;
        work[k * kLanes + g] += m_rhsValue[static_cast<std::size_t>(q)];
        int length = 0;
        for (int j = k; j != -1 && m_mark[static_cast<std::size_t>(j)] != first;
             j = m_parent[static_cast<std::size_t>(j)]) {
          m_mark[static_cast<std::size_t>(j)] = first;
          m_path[static_cast<std::size_t>(length++)] = j;
        }
        top -= length;
        std::copy(m_path.begin(), m_path.begin() + length, m_stack.begin() + top);
      }
    for (int t = top; t < n; ++t) {
      const int j = m_stack[static_cast<std::size_t>(t)];
      // The group's values as one SIMD vector (a copy: the column writes below it).
      const Lanes y = Eigen::Map<const Lanes>(work + j * kLanes);
      if (y.isZero(0.0)) continue;
      for (int p = start[j]; p < start[j + 1]; ++p)
        Eigen::Map<Lanes>(work + rows[p] * kLanes) -= values[p] * y;
    }
    // Keep D^-1/2 y on the reached rows; give each newly reached dof a row of the block.
    for (int g = 0; g < lanes; ++g) {
      for (int t = top; t < n; ++t) {
        const int j = m_stack[static_cast<std::size_t>(t)];
        const double y = work[j * kLanes + g];
        const double d = D[j];
        positive = positive && d > 0;
        if (y == 0 || !(d > 0)) continue;
        int& slot = m_slot[static_cast<std::size_t>(j)];
        if (slot < 0) {
          slot = static_cast<int>(m_reached.size());
          m_reached.push_back(j);
        }
        m_reachIndex.push_back(slot);
        m_reachValue.push_back(y / std::sqrt(d));
      }
      m_reachStart[static_cast<std::size_t>(first + g) + 1] =
          static_cast<int>(m_reachIndex.size());
    }
    for (int t = top; t < n; ++t)
      std::fill_n(work + m_stack[static_cast<std::size_t>(t)] * kLanes, kLanes, 0.0);
  }
  std::fill(m_mark.begin(), m_mark.end(), -1);
  for (int j : m_reached) m_slot[static_cast<std::size_t>(j)] = -1;
  return positive;
}

// The solutions as the columns of a dense block over the reached dofs (kept storage).
LdltCompliance::Block LdltCompliance::gatherBlock() {
  const auto u = static_cast<Eigen::Index>(m_reached.size());
  const auto count = static_cast<Eigen::Index>(m_reachStart.size()) - 1;
  if (m_storage.rows() < u || m_storage.cols() < count)
    m_storage.resize(std::max(u, m_storage.rows()), std::max(count, m_storage.cols()));
  Block Y(m_storage.data(), u, count, Eigen::OuterStride<>(m_storage.rows()));
  Y.setZero();
  for (Eigen::Index r = 0; r < count; ++r)
    for (int p = m_reachStart[static_cast<std::size_t>(r)];
         p < m_reachStart[static_cast<std::size_t>(r) + 1]; ++p)
      Y(m_reachIndex[static_cast<std::size_t>(p)], r) = m_reachValue[static_cast<std::size_t>(p)];
  return Y;
}

}  // namespace stroma
