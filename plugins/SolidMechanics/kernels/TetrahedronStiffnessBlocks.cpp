// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/TetrahedronStiffnessBlocks.h"

#include <algorithm>

namespace stroma::fem {

std::optional<LameParameters> findLameParameters(const Matrix6d& C) {
  const LameParameters lame{C(0, 1), C(3, 3)};
  const Matrix6d isotropic = computeElasticityMatrix(lame);
  if ((C - isotropic).cwiseAbs().maxCoeff() > 1e-12 * C.cwiseAbs().maxCoeff()) return std::nullopt;
  return lame;
}

void TetrahedronStiffnessBlocks::setPattern(std::span<const Tetrahedron> elements,
                                            std::size_t pointCount) {
  // Row i: the vertices of the elements around i, sorted, once each (i among them).
  std::vector<std::uint32_t> elementStart(pointCount + 1, 0), elementsAround;
  for (const Tetrahedron& t : elements)
    for (std::uint32_t v : t) ++elementStart[v + 1];
  for (std::size_t v = 0; v < pointCount; ++v) elementStart[v + 1] += elementStart[v];
  elementsAround.resize(elementStart[pointCount]);
  std::vector<std::uint32_t> next(elementStart.begin(), elementStart.end() - 1);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (std::uint32_t v : elements[e]) elementsAround[next[v]++] = static_cast<std::uint32_t>(e);
  m_rowStart.assign(1, 0);
  m_columns.clear();
  std::vector<std::uint32_t> row;
  for (std::size_t i = 0; i < pointCount; ++i) {
    row.clear();
    for (std::uint32_t k = elementStart[i]; k < elementStart[i + 1]; ++k)
      for (std::uint32_t v : elements[elementsAround[k]]) row.push_back(v);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    m_columns.insert(m_columns.end(), row.begin(), row.end());
    m_rowStart.push_back(static_cast<std::uint32_t>(m_columns.size()));
  }
  const auto blockOf = [this](std::uint32_t i, std::uint32_t j) {
    const auto first = m_columns.begin() + m_rowStart[i],
               last = m_columns.begin() + m_rowStart[i + 1];
    return static_cast<std::uint32_t>(std::lower_bound(first, last, j) - m_columns.begin());
  };
  // Each element's node pairs (a, b) with n_a <= n_b go to block (n_a, n_b): counted, then
  // placed in element order (a counting sort).
  m_contributionStart.assign(m_columns.size() + 1, 0);
  const auto forEachUpperPair = [&](auto&& visit) {
    for (std::size_t e = 0; e < elements.size(); ++e)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          if (elements[e][a] <= elements[e][b])
            visit(blockOf(elements[e][a], elements[e][b]),
                  static_cast<std::uint32_t>(e * 16 + a * 4 + b));
  };
  forEachUpperPair([&](std::uint32_t k, std::uint32_t) { ++m_contributionStart[k + 1]; });
  for (std::size_t k = 0; k < m_columns.size(); ++k)
    m_contributionStart[k + 1] += m_contributionStart[k];
  m_contributions.resize(m_contributionStart.back());
  next.assign(m_contributionStart.begin(), m_contributionStart.end() - 1);
  forEachUpperPair([&](std::uint32_t k, std::uint32_t c) { m_contributions[next[k]++] = c; });
  // A lower block is the transpose of its mirror.
  m_mirror.resize(m_columns.size());
  for (std::uint32_t i = 0; i < pointCount; ++i)
    for (std::uint32_t k = m_rowStart[i]; k < m_rowStart[i + 1]; ++k)
      m_mirror[k] = m_columns[k] < i ? blockOf(m_columns[k], i) : k;
  m_blocks.assign(m_columns.size(), Block::Zero());
  m_rotatedFactors.assign(elements.size(), TetrahedronVectors::Zero());
}

void TetrahedronStiffnessBlocks::rotateFactors(std::span<const Eigen::Matrix3d> rotations,
                                               std::span<const TetrahedronRows> factors,
                                               std::size_t begin, std::size_t end) {
  for (std::size_t e = begin; e < end; ++e)
    m_rotatedFactors[e].noalias() = rotations[e] * fromRows(factors[e]);
}

void TetrahedronStiffnessBlocks::fillUpperBlocks(const LameParameters& lame, std::size_t begin,
                                                 std::size_t end) {
  for (std::size_t i = begin; i < end; ++i)
    for (std::uint32_t k = m_rowStart[i]; k < m_rowStart[i + 1]; ++k) {
      if (m_columns[k] < i) continue;
      // P = sum of (R g_a)(R g_b)^T over the block's elements.
      Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
      for (std::uint32_t c = m_contributionStart[k]; c < m_contributionStart[k + 1]; ++c) {
        const std::uint32_t code = m_contributions[c];
        const TetrahedronVectors& g = m_rotatedFactors[code / 16];
        P.noalias() += g.col((code / 4) % 4) * g.col(code % 4).transpose();
      }
      // K = lambda P + mu P^T + mu tr(P) I, written out: Eigen's expression went through the
      // stack and stalled on the transposed reads (45 % of this loop).
      const double muTrace = lame.mu * P.trace();
      Block& K = m_blocks[k];
      for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) K(r, c) = lame.lambda * P(r, c) + lame.mu * P(c, r);
        K(c, c) += muTrace;
        K(3, c) = 0;
      }
    }
}

void TetrahedronStiffnessBlocks::fillLowerBlocks(std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i)
    for (std::uint32_t k = m_rowStart[i]; k < m_rowStart[i + 1] && m_columns[k] < i; ++k)
      m_blocks[k].topRows<3>() = m_blocks[m_mirror[k]].topRows<3>().transpose();
}

void TetrahedronStiffnessBlocks::multiply(std::span<const Eigen::Vector3d> v,
                                          std::span<Eigen::Vector3d> out, double factor,
                                          std::size_t begin, std::size_t end) const {
  for (std::size_t i = begin; i < end; ++i) {
    Eigen::Vector4d sum = Eigen::Vector4d::Zero();
    for (std::uint32_t k = m_rowStart[i]; k < m_rowStart[i + 1]; ++k) {
      const Block& K = m_blocks[k];
      const Eigen::Vector3d& x = v[m_columns[k]];
      sum.noalias() += K.col(0) * x[0] + K.col(1) * x[1] + K.col(2) * x[2];
    }
    out[i] += factor * sum.head<3>();
  }
}

Eigen::Matrix3d TetrahedronStiffnessBlocks::block(std::size_t i, std::size_t j) const {
  const auto first = m_columns.begin() + m_rowStart[i],
             last = m_columns.begin() + m_rowStart[i + 1];
  const auto it = std::lower_bound(first, last, j);
  if (it == last || *it != j) return Eigen::Matrix3d::Zero();
  return m_blocks[static_cast<std::size_t>(it - m_columns.begin())].topRows<3>();
}

}  // namespace stroma::fem
