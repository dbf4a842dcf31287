// SPDX-License-Identifier: MIT
// LdltCompliance: W += f J A^-1 J^T from a SimplicialLDLT factorization equals the dense
// product, whether it solves by the rows of J (more columns than rows) or by the columns it
// touches (three rows per contact on a vertex), with explicit zeros in J, on top of what W held;
// an indefinite A is refused and leaves W alone.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <random>

#include "LinearSolver/src/LdltCompliance.h"

namespace stroma::test {
namespace {

using SpMat = Eigen::SparseMatrix<double>;
using RowMatrix = LdltCompliance::RowMatrix;

// A 3D lattice of n^3 nodes with 3 dofs each, coupled to their neighbours: a sparse symmetric
// matrix with the fill of a mesh (diagonal shift `shift`: positive definite for shift > 0).
SpMat latticeMatrix(int n, double shift) {
  const int dofs = 3 * n * n * n;
  std::vector<Eigen::Triplet<double>> t;
  auto node = [n](int i, int j, int k) { return (i * n + j) * n + k; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int a = node(i, j, k);
        const int di[] = {1, 0, 0}, dj[] = {0, 1, 0}, dk[] = {0, 0, 1};
        for (int e = 0; e < 3; ++e) {
          if (i + di[e] >= n || j + dj[e] >= n || k + dk[e] >= n) continue;
          const int b = node(i + di[e], j + dj[e], k + dk[e]);
          for (int c = 0; c < 3; ++c)
            for (int d = 0; d < 3; ++d) {
              const double w = (c == d ? 1.0 : 0.2) * (1 + 0.1 * e);
              t.emplace_back(3 * a + c, 3 * a + d, w);
              t.emplace_back(3 * b + c, 3 * b + d, w);
              t.emplace_back(3 * a + c, 3 * b + d, -w);
              t.emplace_back(3 * b + c, 3 * a + d, -w);
            }
        }
      }
  for (int r = 0; r < dofs; ++r) t.emplace_back(r, r, shift);
  SpMat A(dofs, dofs);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// `contacts` groups of three rows (normal, two tangents) on the dofs of `vertices` of the first
// `nodes` nodes each, the first vertex's weight 1 and the others' 0 (explicit zeros, as a
// contact on a triangle's vertex carries them) when onVertex, random weights otherwise; J has
// the `columns` of A.
RowMatrix contactRows(int columns, int nodes, int contacts, int vertices, bool onVertex,
                      unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> pick(0, nodes - 1);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < contacts; ++c) {
    std::vector<int> nodesOf;
    while (static_cast<int>(nodesOf.size()) < vertices) {
      const int v = pick(random);
      if (std::find(nodesOf.begin(), nodesOf.end(), v) == nodesOf.end()) nodesOf.push_back(v);
    }
    std::vector<double> weight(static_cast<std::size_t>(vertices));
    for (int v = 0; v < vertices; ++v) weight[v] = onVertex ? (v == 0 ? 1.0 : 0.0) : u(random);
    for (int r = 0; r < 3; ++r) {
      const Eigen::Vector3d direction = Eigen::Vector3d(u(random), u(random), u(random)).normalized();
      for (int v = 0; v < vertices; ++v)
        for (int a = 0; a < 3; ++a)
          t.emplace_back(3 * c + r, 3 * nodesOf[v] + a, weight[v] * direction[a]);
    }
  }
  RowMatrix J(3 * contacts, columns);
  J.setFromTriplets(t.begin(), t.end());
  return J;
}

void expectDenseProduct(const SpMat& A, const RowMatrix& J, double factor) {
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower> ldlt(A);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  LdltCompliance compliance;
  compliance.setFactor(ldlt.matrixL().nestedExpression());
  const auto m = J.rows();
  // W starts symmetric and non-zero, as when another body's compliance is already in it.
  Eigen::MatrixXd W = Eigen::MatrixXd::Random(m, m);
  W = (W + W.transpose()).eval();
  const Eigen::MatrixXd before = W;
  ASSERT_TRUE(compliance.add(ldlt.matrixL().nestedExpression(), ldlt.vectorD(),
                             ldlt.permutationP().indices(), J, factor, W));
  const Eigen::MatrixXd Jd(J);
  const Eigen::MatrixXd expected =
      before + factor * Jd * Eigen::MatrixXd(A).ldlt().solve(Jd.transpose());
  EXPECT_LT((W - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  // Again with the same buffers (a warm step).
  W = before;
  ASSERT_TRUE(compliance.add(ldlt.matrixL().nestedExpression(), ldlt.vectorD(),
                             ldlt.permutationP().indices(), J, factor, W));
  EXPECT_LT((W - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

TEST(LdltCompliance, ByRowsEqualsTheDenseProduct) {
  // 20 contacts on triangles (9 columns each): more columns than rows.
  const SpMat A = latticeMatrix(6, 0.5);
  expectDenseProduct(A, contactRows(648, 216, 20, 3, false, 1), 0.7);
}

TEST(LdltCompliance, ByColumnsEqualsTheDenseProduct) {
  // 150 contacts on the vertices of 40 nodes: more rows than columns, so the columns' block,
  // then J X J^T; the explicit zeros (a triangle's other vertices) are left out.
  const SpMat A = latticeMatrix(6, 0.5);
  expectDenseProduct(A, contactRows(648, 40, 150, 3, true, 2), 1e-4);
}

TEST(LdltCompliance, RefusesAnIndefiniteMatrixAndLeavesWAlone) {
  const SpMat A = latticeMatrix(4, -0.3);  // the shift makes a negative eigenvalue
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower> ldlt(A);
  ASSERT_LT(ldlt.vectorD().minCoeff(), 0.0);
  LdltCompliance compliance;
  compliance.setFactor(ldlt.matrixL().nestedExpression());
  const RowMatrix J = contactRows(192, 64, 10, 3, false, 3);
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(J.rows(), J.rows());
  EXPECT_FALSE(compliance.add(ldlt.matrixL().nestedExpression(), ldlt.vectorD(),
                              ldlt.permutationP().indices(), J, 1.0, W));
  EXPECT_EQ(W, Eigen::MatrixXd::Identity(J.rows(), J.rows()));
}

}  // namespace
}  // namespace stroma::test
