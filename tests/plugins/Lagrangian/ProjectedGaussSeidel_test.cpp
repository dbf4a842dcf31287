// SPDX-License-Identifier: MIT
// The projected Gauss-Seidel of the constraint solvers (plugins/Lagrangian/src/
// ProjectedGaussSeidel.h) on random small problems: every solution meets its laws
// (complementarity, Coulomb cones, bilateral rows held) to the solver's tolerance, and the
// solution of a problem with a unique solution does not depend on the order of the groups.
#include <gtest/gtest.h>

#include <random>

#include "Lagrangian/src/ProjectedGaussSeidel.h"

namespace stroma::test {
namespace {

using lagrangian::GaussSeidelSettings;
using lagrangian::solveProjectedGaussSeidel;

// W = H C H^T for random rows H and a diagonal C > 0: symmetric positive definite when the rows
// are independent.
Eigen::MatrixXd randomCompliance(int rows, std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd H(rows, rows + 4);
  for (int i = 0; i < H.rows(); ++i)
    for (int j = 0; j < H.cols(); ++j) H(i, j) = u(random);
  Eigen::VectorXd c(rows + 4);
  for (int j = 0; j < c.size(); ++j) c[j] = 0.5 + 0.5 * (u(random) + 1);
  return 1e-3 * H * c.asDiagonal() * H.transpose();
}

struct Problem {
  Eigen::MatrixXd W;
  Eigen::VectorXd violation;
  std::vector<ConstraintGroup> groups;
};

Problem randomProblem(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Problem p;
  std::size_t row = 0;
  // Two bilateral rows, three unilateral ones, three friction contacts.
  for (int k = 0; k < 2; ++k) p.groups.push_back({ConstraintKind::bilateral, row++, 1, 0});
  for (int k = 0; k < 3; ++k) p.groups.push_back({ConstraintKind::unilateral, row++, 1, 0});
  for (int k = 0; k < 3; ++k) {
    p.groups.push_back({ConstraintKind::friction, row, 3, 0.3 + 0.2 * k});
    row += 3;
  }
  p.W = randomCompliance(static_cast<int>(row), random);
  p.violation.resize(static_cast<Eigen::Index>(row));
  for (Eigen::Index i = 0; i < p.violation.size(); ++i) p.violation[i] = 0.01 * u(random);
  return p;
}

// The largest breach of the laws, as a displacement (m) for the rows or a force for the cones.
void expectLawsHold(const Problem& p, const Eigen::VectorXd& lambda, double tolerance) {
  const Eigen::VectorXd delta = p.violation + p.W * lambda;
  for (const ConstraintGroup& g : p.groups) {
    const auto r = static_cast<Eigen::Index>(g.firstRow);
    switch (g.kind) {
      case ConstraintKind::bilateral:
        EXPECT_NEAR(delta[r], 0, tolerance) << "bilateral row " << r;
        break;
      case ConstraintKind::unilateral:
      case ConstraintKind::friction: {
        EXPECT_GE(lambda[r], 0) << "row " << r;
        EXPECT_GE(delta[r], -tolerance) << "row " << r;
        EXPECT_NEAR(lambda[r] * delta[r], 0, tolerance * std::abs(lambda[r]) + 1e-15) << "row " << r;
        if (g.kind == ConstraintKind::unilateral) break;
        const Eigen::Vector2d t(lambda[r + 1], lambda[r + 2]);
        EXPECT_LE(t.norm(), g.mu * lambda[r] * (1 + 1e-12) + 1e-15) << "cone of row " << r;
        // Sticking inside the cone: no slip.
        if (t.norm() < g.mu * lambda[r] * (1 - 1e-6)) {
          EXPECT_NEAR(delta[r + 1], 0, tolerance) << "stick row " << r + 1;
          EXPECT_NEAR(delta[r + 2], 0, tolerance) << "stick row " << r + 2;
        }
        break;
      }
    }
  }
}

TEST(ProjectedGaussSeidel, SolutionsMeetTheirLaws) {
  // 50 random problems of 17 rows; tolerance 1e-10 m per sweep. The laws then hold to 1e-8 m
  // (measured: the last sweep's changes bound the remaining breach).
  for (unsigned seed = 1; seed <= 50; ++seed) {
    SCOPED_TRACE(seed);
    const Problem p = randomProblem(seed);
    Eigen::VectorXd lambda;
    const ConstraintSolveReport report = solveProjectedGaussSeidel(
        p.W, p.violation, p.groups, {.maxIterations = 100000, .tolerance = 1e-12}, lambda);
    EXPECT_TRUE(report.converged) << report.iterations << " sweeps, error " << report.error;
    expectLawsHold(p, lambda, 1e-8);
  }
}

TEST(ProjectedGaussSeidel, UnilateralAndBilateralSolutionsDoNotDependOnTheOrder) {
  // Without friction the problem is a convex quadratic program with a unique solution (W
  // positive definite): the groups in reverse order give the same multipliers.
  for (unsigned seed = 1; seed <= 20; ++seed) {
    Problem p = randomProblem(seed);
    std::vector<ConstraintGroup> frictionless;
    for (const ConstraintGroup& g : p.groups)
      if (g.kind != ConstraintKind::friction) frictionless.push_back(g);
    const Eigen::Index rows = static_cast<Eigen::Index>(frictionless.size());
    Problem q{p.W.topLeftCorner(rows, rows), p.violation.head(rows), frictionless};
    Eigen::VectorXd forward, backward;
    solveProjectedGaussSeidel(q.W, q.violation, q.groups, {.maxIterations = 100000, .tolerance = 1e-14},
                              forward);
    std::vector<ConstraintGroup> reversed(q.groups.rbegin(), q.groups.rend());
    solveProjectedGaussSeidel(q.W, q.violation, reversed, {.maxIterations = 100000, .tolerance = 1e-14},
                              backward);
    EXPECT_LT((forward - backward).norm(), 1e-8 * (1 + forward.norm())) << "seed " << seed;
  }
}

TEST(ProjectedGaussSeidel, ABlockOnASlopeSticksOrSlidesAsCoulombSays) {
  // One contact, W = identity compliance c: a tangential push (the slip of the free motion)
  // against a normal load. With delta_n = -a (the free motion goes a into the ground) the
  // normal force is a / c; the tangential force cancels the slip s while s / c <= mu a / c.
  const double c = 1e-3, a = 0.01;
  const Eigen::MatrixXd W = c * Eigen::MatrixXd::Identity(3, 3);
  const std::vector<ConstraintGroup> contact{{ConstraintKind::friction, 0, 3, 0.5}};
  for (const double slip : {0.001, 0.004, 0.006, 0.02}) {
    Eigen::VectorXd lambda;
    const Eigen::VectorXd violation = Eigen::Vector3d(-a, slip, 0);
    solveProjectedGaussSeidel(W, violation, contact, {.tolerance = 1e-14}, lambda);
    EXPECT_NEAR(lambda[0], a / c, 1e-9);
    const double expected = std::min(slip / c, 0.5 * a / c);
    EXPECT_NEAR(-lambda[1], expected, 1e-9) << "slip " << slip;
    EXPECT_NEAR(lambda[2], 0, 1e-12);
  }
}

}  // namespace
}  // namespace stroma::test
