// SPDX-License-Identifier: MIT
#include "SymmetricBlockMatrix.h"

#include <algorithm>
#include <stdexcept>

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

namespace stroma::multigrid {

namespace {
/// Values after the last block, so that 4-wide loads of its last column stay in the array.
constexpr std::size_t kPadding = 3;
/// The destination of an entry below the diagonal blocks (not stored).
constexpr std::uint32_t kLower = 0xffffffffu;
}  // namespace

void SymmetricBlockMatrix::buildPattern(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() != A.cols() || A.rows() % 3 != 0)
    throw std::invalid_argument("SymmetricBlockMatrix: the matrix is not square with 3n rows");
  m_blockColumnCount = std::size_t(A.cols() / 3);
  m_columnStarts.assign(m_blockColumnCount + 1, 0);
  m_blockRows.clear();
  m_destination.resize(std::size_t(A.nonZeros()));
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  // Per block column: the union of the block rows I <= J of its 3 columns (the upper triangle,
  // diagonal block last), then each entry's place; entries below the diagonal blocks are not
  // copied.
  std::vector<std::uint32_t> rows;
  for (std::size_t J = 0; J < m_blockColumnCount; ++J) {
    rows.clear();
    for (int k = outer[3 * J]; k < outer[3 * J + 3]; ++k)
      if (std::size_t(inner[k] / 3) <= J) rows.push_back(std::uint32_t(inner[k] / 3));
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    const std::size_t first = m_blockRows.size();
    m_blockRows.insert(m_blockRows.end(), rows.begin(), rows.end());
    m_columnStarts[J + 1] = std::uint32_t(m_blockRows.size());
    for (std::size_t j = 0; j < 3; ++j)
      for (int k = outer[3 * J + j]; k < outer[3 * J + j + 1]; ++k) {
        const std::uint32_t I = std::uint32_t(inner[k] / 3);
        if (I > J) {
          m_destination[std::size_t(k)] = kLower;
          continue;
        }
        const std::size_t slot =
            std::size_t(std::lower_bound(rows.begin(), rows.end(), I) - rows.begin());
        m_destination[std::size_t(k)] =
            std::uint32_t(9 * (first + slot) + 3 * std::size_t(inner[k] % 3) + j);
      }
  }
}

template <class Scalar>
void SymmetricBlockMatrix::fill(const Eigen::SparseMatrix<double>& A, std::vector<Scalar>& values,
                                bool newPattern) const {
  // The slots no entry of A reaches (the rest of a partly stored block, the padding) stay zero
  // from the last zeroing while the pattern holds: a refill only overwrites the entries.
  if (newPattern || values.size() != 9 * m_blockRows.size() + kPadding)
    values.assign(9 * m_blockRows.size() + kPadding, Scalar(0));
  const double* source = A.valuePtr();
  const std::size_t count = m_destination.size();
  for (std::size_t k = 0; k < count; ++k)
    if (m_destination[k] != kLower) values[m_destination[k]] = Scalar(source[k]);
}

void SymmetricBlockMatrix::assign(const Eigen::SparseMatrix<double>& A, Precision precision,
                         bool samePattern) {
  if (!A.isCompressed())
    throw std::invalid_argument("SymmetricBlockMatrix: the matrix is not in compressed form");
  const bool newPattern =
      !samePattern || std::size_t(A.nonZeros()) != m_destination.size() || A.rows() != rows();
  if (newPattern) buildPattern(A);
  m_precision = precision;
  if (precision == Precision::single) {
    fill(A, m_single, newPattern);
    m_double.clear();
  } else {
    fill(A, m_double, newPattern);
    m_single.clear();
  }
}

namespace {

#if defined(__AVX2__) && defined(__FMA__)
/// The 4 values at `p` as doubles (the 4th belongs to the next column or block: ignored).
inline __m256d load4(const double* p) { return _mm256_loadu_pd(p); }
inline __m256d load4(const float* p) { return _mm256_cvtps_pd(_mm_loadu_ps(p)); }
#endif

}  // namespace

template <class Scalar>
void SymmetricBlockMatrix::multiplyWith(const std::vector<Scalar>& values,
                                        const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.resize(rows());
  double* out = y.data();
  const double* in = x.data();
  const Scalar* block = values.data();
  // Column J: y_J = sum over I <= J of B_IJ^T x_I, stored (the blocks of later columns add to it
  // afterwards), and y_I += B_IJ x_J for I < J (rows already stored). S = B_IJ^T is stored
  // column-major: y_J gathers S x_I, y_I receives S^T x_J.
  for (std::size_t J = 0; J < m_blockColumnCount; ++J) {
    const double* xJ = in + 3 * J;
#if defined(__AVX2__) && defined(__FMA__)
    const __m256d xJ0 = _mm256_broadcast_sd(xJ), xJ1 = _mm256_broadcast_sd(xJ + 1),
                  xJ2 = _mm256_broadcast_sd(xJ + 2), zero = _mm256_setzero_pd();
    __m256d sum = zero;
    for (std::uint32_t k = m_columnStarts[J]; k < m_columnStarts[J + 1]; ++k, block += 9) {
      const std::size_t I = m_blockRows[k];
      const double* xI = in + 3 * I;
      // S's columns (lane 3: the next value, unused).
      const __m256d c0 = load4(block), c1 = load4(block + 3), c2 = load4(block + 6);
      sum = _mm256_fmadd_pd(c0, _mm256_broadcast_sd(xI), sum);
      sum = _mm256_fmadd_pd(c1, _mm256_broadcast_sd(xI + 1), sum);
      sum = _mm256_fmadd_pd(c2, _mm256_broadcast_sd(xI + 2), sum);
      if (I == J) continue;  // the diagonal block (last of its column) counts once
      // S^T x_J = sum_r x_J[r] (row r of S): the rows by a 3 x 3 transpose in registers.
      const __m256d t0 = _mm256_unpacklo_pd(c0, c1), t1 = _mm256_unpackhi_pd(c0, c1),
                    t2 = _mm256_unpacklo_pd(c2, zero), t3 = _mm256_unpackhi_pd(c2, zero);
      const __m256d r0 = _mm256_permute2f128_pd(t0, t2, 0x20),
                    r1 = _mm256_permute2f128_pd(t1, t3, 0x20),
                    r2 = _mm256_permute2f128_pd(t0, t2, 0x31);
      const __m256d v =
          _mm256_fmadd_pd(r2, xJ2, _mm256_fmadd_pd(r1, xJ1, _mm256_mul_pd(r0, xJ0)));
      // Exactly y_I's 3 values: a 4-wide store would overlap y_{I+1}, often the next block's
      // row, and stall the load that follows.
      double* yI = out + 3 * I;
      _mm_storeu_pd(yI, _mm_add_pd(_mm_loadu_pd(yI), _mm256_castpd256_pd128(v)));
      yI[2] += _mm_cvtsd_f64(_mm256_extractf128_pd(v, 1));
    }
    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, sum);
    out[3 * J] = lanes[0];
    out[3 * J + 1] = lanes[1];
    out[3 * J + 2] = lanes[2];
#else
    const double x0 = xJ[0], x1 = xJ[1], x2 = xJ[2];
    double s0 = 0, s1 = 0, s2 = 0;
    for (std::uint32_t k = m_columnStarts[J]; k < m_columnStarts[J + 1]; ++k, block += 9) {
      const std::size_t I = m_blockRows[k];
      const double* xI = in + 3 * I;
      s0 += double(block[0]) * xI[0] + double(block[3]) * xI[1] + double(block[6]) * xI[2];
      s1 += double(block[1]) * xI[0] + double(block[4]) * xI[1] + double(block[7]) * xI[2];
      s2 += double(block[2]) * xI[0] + double(block[5]) * xI[1] + double(block[8]) * xI[2];
      if (I == J) continue;  // the diagonal block (last of its column) counts once
      double* yI = out + 3 * I;
      yI[0] += double(block[0]) * x0 + double(block[1]) * x1 + double(block[2]) * x2;
      yI[1] += double(block[3]) * x0 + double(block[4]) * x1 + double(block[5]) * x2;
      yI[2] += double(block[6]) * x0 + double(block[7]) * x1 + double(block[8]) * x2;
    }
    out[3 * J] = s0;
    out[3 * J + 1] = s1;
    out[3 * J + 2] = s2;
#endif
  }
}

void SymmetricBlockMatrix::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  if (m_precision == Precision::single)
    multiplyWith(m_single, x, y);
  else
    multiplyWith(m_double, x, y);
}

}  // namespace stroma::multigrid
