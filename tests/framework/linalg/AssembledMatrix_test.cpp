// SPDX-License-Identifier: MIT
// AssembledMatrix: entries and 3x3 blocks sum up like a dense matrix; a repeated sequence of
// calls refills the same pattern in place (patternRevision unchanged); a sequence that changes
// in the middle, ends early or goes on longer gives the same matrix as a fresh assembly.
#include "linalg/AssembledMatrix.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <random>
#include <vector>

namespace stroma::test {
namespace {

/// One call of an assembly: a scalar entry or a 3x3 block.
struct Call {
  std::size_t row, col;
  bool block;
  Eigen::Matrix3d values;
};

std::vector<Call> randomCalls(std::mt19937& random, std::size_t n, int count) {
  std::uniform_int_distribution<std::size_t> blockIndex(0, n / 3 - 1), index(0, n - 1);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<Call> calls;
  for (int k = 0; k < count; ++k) {
    Call c;
    c.block = k % 3 != 0;
    c.row = c.block ? 3 * blockIndex(random) : index(random);
    c.col = c.block ? 3 * blockIndex(random) : index(random);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c.values(i, j) = value(random);
    calls.push_back(c);
  }
  return calls;
}

Eigen::MatrixXd dense(std::size_t n, const std::vector<Call>& calls) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  for (const Call& c : calls) {
    if (c.block)
      D.block<3, 3>(Eigen::Index(c.row), Eigen::Index(c.col)) += c.values;
    else
      D(Eigen::Index(c.row), Eigen::Index(c.col)) += c.values(0, 0);
  }
  return D;
}

void assemble(AssembledMatrix& A, std::size_t n, const std::vector<Call>& calls) {
  A.begin(n);
  for (const Call& c : calls) {
    if (c.block)
      A.addBlock(c.row, c.col, c.values);
    else
      A.add(c.row, c.col, c.values(0, 0));
  }
  A.finish();
}

double difference(const AssembledMatrix& A, const Eigen::MatrixXd& expected) {
  return (Eigen::MatrixXd(A.matrix()) - expected).cwiseAbs().maxCoeff();
}

/// The pattern holds the places the calls touched, and nothing else.
Eigen::Index touched(std::size_t n, const std::vector<Call>& calls) {
  Eigen::MatrixXi T = Eigen::MatrixXi::Zero(Eigen::Index(n), Eigen::Index(n));
  for (const Call& c : calls) {
    if (c.block)
      T.block<3, 3>(Eigen::Index(c.row), Eigen::Index(c.col)).setOnes();
    else
      T(Eigen::Index(c.row), Eigen::Index(c.col)) = 1;
  }
  return T.sum();
}

TEST(AssembledMatrix, EntriesAndBlocksSumUpAndRefillInPlace) {
  std::mt19937 random(7);
  const std::size_t n = 30;
  const std::vector<Call> calls = randomCalls(random, n, 200);
  AssembledMatrix A;
  assemble(A, n, calls);
  EXPECT_LT(difference(A, dense(n, calls)), 1e-14);
  EXPECT_EQ(A.matrix().nonZeros(), touched(n, calls));
  const auto revision = A.patternRevision();

  // Same places, new values: refilled in place.
  std::vector<Call> again = calls;
  for (Call& c : again) c.values *= -2.5;
  assemble(A, n, again);
  EXPECT_EQ(A.patternRevision(), revision);
  EXPECT_LT(difference(A, dense(n, again)), 1e-13);
}

TEST(AssembledMatrix, ChangedSequencesGiveTheFreshMatrix) {
  std::mt19937 random(11);
  const std::size_t n = 24;
  const std::vector<Call> calls = randomCalls(random, n, 120);

  // A call in the middle goes elsewhere (a block becomes an entry, then a block moves).
  for (std::size_t changed : {std::size_t{0}, std::size_t{1}, std::size_t{60}, std::size_t{119}}) {
    AssembledMatrix A;
    assemble(A, n, calls);
    const auto revision = A.patternRevision();
    std::vector<Call> other = calls;
    other[changed].block = !other[changed].block;
    other[changed].row = other[changed].block ? 3 * (other[changed].row / 3) : n - 1;
    other[changed].col = other[changed].block ? 3 * (other[changed].col / 3) : 0;
    assemble(A, n, other);
    EXPECT_NE(A.patternRevision(), revision) << "call " << changed;
    EXPECT_LT(difference(A, dense(n, other)), 1e-13) << "call " << changed;
    EXPECT_EQ(A.matrix().nonZeros(), touched(n, other)) << "call " << changed;
    // And back: a third assembly with the first sequence.
    assemble(A, n, calls);
    EXPECT_LT(difference(A, dense(n, calls)), 1e-13) << "call " << changed;
  }

  // Ends early: the pattern shrinks to what was touched.
  AssembledMatrix A;
  assemble(A, n, calls);
  const std::vector<Call> shorter(calls.begin(), calls.begin() + 50);
  assemble(A, n, shorter);
  EXPECT_LT(difference(A, dense(n, shorter)), 1e-13);
  EXPECT_EQ(A.matrix().nonZeros(), touched(n, shorter));

  // Goes on longer.
  std::vector<Call> longer = calls;
  const std::vector<Call> more = randomCalls(random, n, 30);
  longer.insert(longer.end(), more.begin(), more.end());
  assemble(A, n, longer);
  EXPECT_LT(difference(A, dense(n, longer)), 1e-13);
  EXPECT_EQ(A.matrix().nonZeros(), touched(n, longer));

  // Another size starts over.
  const std::vector<Call> small = randomCalls(random, 9, 20);
  assemble(A, 9, small);
  EXPECT_EQ(A.matrix().rows(), 9);
  EXPECT_LT(difference(A, dense(9, small)), 1e-13);
}

/// Forwards entries and blocks to an AssembledMatrix, element matrices through the default
/// addBlocks (block by block), as a filtering accumulator does.
class BlockByBlock final : public MatrixAccumulator {
 public:
  explicit BlockByBlock(AssembledMatrix& target) : m_target(target) {}
  void add(std::size_t row, std::size_t col, double value) override {
    m_target.add(row, col, value);
  }
  void addBlock(std::size_t row, std::size_t col, const Eigen::Matrix3d& block) override {
    m_target.addBlock(row, col, block);
  }

 private:
  AssembledMatrix& m_target;
};

/// One element matrix per entry of `nodes`: 4 nodes, 12 x 12 values.
struct Elements {
  std::vector<std::array<std::size_t, 4>> offsets;
  std::vector<Eigen::Matrix<double, 12, 12>> matrices;
};

Elements randomElements(std::mt19937& random, std::size_t nodes, int count) {
  std::uniform_int_distribution<std::size_t> node(0, nodes - 1);
  Elements elements;
  for (int e = 0; e < count; ++e) {
    elements.offsets.push_back({3 * node(random), 3 * node(random), 3 * node(random),
                                3 * node(random)});
    elements.matrices.push_back(Eigen::Matrix<double, 12, 12>::Random());
  }
  return elements;
}

/// Assembles factor * each element, in one call each (A) or block by block (through).
void assembleElements(AssembledMatrix& A, MatrixAccumulator& through, std::size_t n,
                      const Elements& elements, double factor) {
  A.begin(n);
  for (std::size_t e = 0; e < elements.offsets.size(); ++e)
    through.addBlocks(elements.offsets[e], elements.matrices[e], factor);
  A.add(0, 1, 0.5);  // an entry after them
  A.finish();
}

TEST(AssembledMatrix, ElementMatricesInOneCallGiveTheSumsOfTheirBlocks) {
  std::mt19937 random(5);
  const std::size_t nodes = 12, n = 3 * nodes;
  const Elements elements = randomElements(random, nodes, 30);
  AssembledMatrix reference, A;
  BlockByBlock blocks(reference);
  assembleElements(reference, blocks, n, elements, -0.7);
  assembleElements(A, A, n, elements, -0.7);  // records: the default
  const Eigen::MatrixXd expected(reference.matrix());
  EXPECT_EQ(Eigen::MatrixXd(A.matrix()), expected);

  // Refilled in place, element by element, then block by block: the same sums (to round-off:
  // the compiler may fuse factor * value + sum into one multiply-add).
  const auto revision = A.patternRevision();
  assembleElements(A, A, n, elements, -0.7);
  EXPECT_EQ(A.patternRevision(), revision);
  EXPECT_LT((Eigen::MatrixXd(A.matrix()) - expected).cwiseAbs().maxCoeff(), 1e-14);
  BlockByBlock throughBlocks(A);
  assembleElements(A, throughBlocks, n, elements, -0.7);
  EXPECT_EQ(A.patternRevision(), revision);
  EXPECT_EQ(Eigen::MatrixXd(A.matrix()), expected);

  // An element whose node changed, in the middle: recorded anew, the fresh matrix.
  Elements other = elements;
  other.offsets[17][2] = 3 * ((other.offsets[17][2] / 3 + 1) % nodes);
  AssembledMatrix fresh;
  BlockByBlock freshBlocks(fresh);
  assembleElements(fresh, freshBlocks, n, other, 2.0);
  assembleElements(A, A, n, other, 2.0);
  EXPECT_NE(A.patternRevision(), revision);
  EXPECT_LT((Eigen::MatrixXd(A.matrix()) - Eigen::MatrixXd(fresh.matrix())).cwiseAbs().maxCoeff(),
            1e-13);
  EXPECT_EQ(A.matrix().nonZeros(), fresh.matrix().nonZeros());
}

TEST(AssembledMatrix, AnEmptyAssemblyKeepsItsPattern) {
  AssembledMatrix A;
  A.begin(6);
  A.finish();
  const auto revision = A.patternRevision();
  EXPECT_EQ(A.matrix().rows(), 6);
  EXPECT_EQ(A.matrix().nonZeros(), 0);
  A.begin(6);
  A.finish();
  EXPECT_EQ(A.patternRevision(), revision);
}

}  // namespace
}  // namespace stroma::test
