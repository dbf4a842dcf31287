// SPDX-License-Identifier: MIT
// SymmetricBlockMatrix: the product of the 3 x 3 block copy equals Eigen's product with the
// source matrix (double to round-off, single to its precision), for blocks stored whole and in
// part (identity rows of fixed points, diagonal-only blocks), after refills with the same
// pattern and after a change of pattern.
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <random>
#include <vector>

#include "SymmetricBlockMatrix.h"

namespace stroma::multigrid {
namespace {

/// A symmetric 3n x 3n matrix: full blocks on a ring of points (i, i +- 1, i +- 5), a point
/// with only diagonal entries, and a "fixed" point whose rows and columns are the identity.
Eigen::SparseMatrix<double> ringMatrix(int n, unsigned seed, bool extraCoupling) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<Eigen::Triplet<double>> entries;
  auto addBlock = [&](int I, int J) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double v = value(random);
        entries.emplace_back(3 * I + a, 3 * J + b, v);
        entries.emplace_back(3 * J + b, 3 * I + a, v);
      }
  };
  const int fixed = 2, diagonalOnly = 4;
  for (int I = 0; I < n; ++I) {
    if (I == fixed || I == diagonalOnly) continue;
    for (int a = 0; a < 3; ++a) entries.emplace_back(3 * I + a, 3 * I + a, 20.0);
    for (int step : {1, 5}) {
      const int J = (I + step) % n;
      if (J != fixed && J != diagonalOnly) addBlock(I, J);
    }
    if (extraCoupling && I + 7 < n && I + 7 != fixed && I + 7 != diagonalOnly) addBlock(I, I + 7);
  }
  for (int a = 0; a < 3; ++a) {
    entries.emplace_back(3 * fixed + a, 3 * fixed + a, 1.0);
    entries.emplace_back(3 * diagonalOnly + a, 3 * diagonalOnly + a, 2.0 + a);
  }
  Eigen::SparseMatrix<double> A(3 * n, 3 * n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

double relativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).norm() / b.norm();
}

TEST(SymmetricBlockMatrix, ProductEqualsTheSourceMatrixProduct) {
  const Eigen::SparseMatrix<double> A = ringMatrix(40, 1, false);
  ASSERT_LT((Eigen::SparseMatrix<double>(A.transpose()) - A).norm(), 1e-15);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  const Eigen::VectorXd expected = A * x;
  SymmetricBlockMatrix blocks;
  blocks.assign(A, SymmetricBlockMatrix::Precision::double_, false);
  EXPECT_EQ(blocks.rows(), A.rows());
  Eigen::VectorXd y;
  blocks.multiply(x, y);
  EXPECT_LT(relativeDifference(y, expected), 1e-15);
  // The upper triangle of blocks: 40 diagonal blocks and one block per coupled pair, less the
  // pairs of the fixed and diagonal-only points.
  std::size_t pairs = 0;
  for (int I = 0; I < 40; ++I)
    for (int step : {1, 5}) {
      const int J = (I + step) % 40;
      if (I != 2 && I != 4 && J != 2 && J != 4) ++pairs;
    }
  EXPECT_EQ(blocks.blockCount(), 40 + pairs);

  blocks.assign(A, SymmetricBlockMatrix::Precision::single, true);
  blocks.multiply(x, y);
  EXPECT_LT(relativeDifference(y, expected), 1e-6);
  EXPECT_GT(relativeDifference(y, expected), 0.0);  // really rounded to single precision
}

TEST(SymmetricBlockMatrix, RefillsValuesAndFollowsAPatternChange) {
  SymmetricBlockMatrix blocks;
  const Eigen::SparseMatrix<double> first = ringMatrix(30, 2, false);
  blocks.assign(first, SymmetricBlockMatrix::Precision::double_, false);
  // Same pattern, new values: only the values are copied.
  const Eigen::SparseMatrix<double> second = ringMatrix(30, 3, false);
  blocks.assign(second, SymmetricBlockMatrix::Precision::double_, true);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(second.rows(), 1.0, -3.0);
  Eigen::VectorXd y;
  blocks.multiply(x, y);
  EXPECT_LT(relativeDifference(y, second * x), 1e-15);
  // A new pattern (more blocks): rebuilt, even when told the pattern is the same, since the
  // number of entries differs.
  const Eigen::SparseMatrix<double> third = ringMatrix(30, 4, true);
  blocks.assign(third, SymmetricBlockMatrix::Precision::double_, true);
  blocks.multiply(x, y);
  EXPECT_LT(relativeDifference(y, third * x), 1e-15);
}

TEST(SymmetricBlockMatrix, RefusesAMatrixThatIsNotOf3x3Blocks) {
  Eigen::SparseMatrix<double> A(4, 4);
  A.setIdentity();
  A.makeCompressed();
  SymmetricBlockMatrix blocks;
  EXPECT_THROW(blocks.assign(A, SymmetricBlockMatrix::Precision::double_, false),
               std::invalid_argument);
}

}  // namespace
}  // namespace stroma::multigrid
