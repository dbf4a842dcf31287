// SPDX-License-Identifier: MIT
// The constraint solvers' algorithms (plugins/Lagrangian/src/ProjectedGaussSeidel.h) on random
// small problems: every solution of projected Gauss-Seidel and of the nonsmooth conjugate
// gradient meets its laws (complementarity, Coulomb cones, bilateral rows held) to the solver's
// tolerance, both give the exact (enumerated) solution of frictionless problems, a solution
// does not depend on the order of the groups, the conjugate gradient needs far fewer sweeps on
// a chain, and one contact's Coulomb step slides against the slip it leaves.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <cstdio>
#include <random>

#include "Lagrangian/src/ProjectedGaussSeidel.h"

namespace stroma::test {
namespace {

using lagrangian::GaussSeidelSettings;
using lagrangian::solveFrictionDisc;
using lagrangian::solveNonsmoothConjugateGradient;
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

// The exact solution of a frictionless problem (bilateral and unilateral rows) by enumeration of
// the unilateral rows that push: for each subset, the pushing rows and the bilateral ones have
// delta = 0, the others lambda = 0; the subset whose solution meets the laws is the answer (W
// positive definite: there is exactly one).
Eigen::VectorXd enumerated(const Eigen::MatrixXd& W, const Eigen::VectorXd& violation,
                           const std::vector<ConstraintGroup>& groups) {
  std::vector<Eigen::Index> unilateral, bilateral;
  for (const ConstraintGroup& g : groups)
    (g.kind == ConstraintKind::unilateral ? unilateral : bilateral)
        .push_back(static_cast<Eigen::Index>(g.firstRow));
  for (unsigned mask = 0; mask < (1u << unilateral.size()); ++mask) {
    std::vector<Eigen::Index> active = bilateral;
    for (std::size_t k = 0; k < unilateral.size(); ++k)
      if (mask & (1u << k)) active.push_back(unilateral[k]);
    const auto a = static_cast<Eigen::Index>(active.size());
    Eigen::MatrixXd Waa(a, a);
    Eigen::VectorXd rhs(a);
    for (Eigen::Index i = 0; i < a; ++i) {
      rhs[i] = -violation[active[i]];
      for (Eigen::Index j = 0; j < a; ++j) Waa(i, j) = W(active[i], active[j]);
    }
    const Eigen::VectorXd la = Waa.ldlt().solve(rhs);
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(violation.size());
    for (Eigen::Index i = 0; i < a; ++i) lambda[active[i]] = la[i];
    const Eigen::VectorXd delta = violation + W * lambda;
    bool ok = true;
    for (Eigen::Index r : unilateral) ok &= lambda[r] >= -1e-12 && delta[r] >= -1e-12;
    if (ok) return lambda;
  }
  ADD_FAILURE() << "no active set meets the laws";
  return {};
}

TEST(ConstraintSolvers, AgreeWithTheExactSolutionOfSmallProblems) {
  // Frictionless problems (2 bilateral and 3 unilateral rows): projected Gauss-Seidel and the
  // nonsmooth conjugate gradient give the enumerated exact multipliers to their tolerance.
  for (unsigned seed = 1; seed <= 30; ++seed) {
    const Problem p = randomProblem(seed);
    std::vector<ConstraintGroup> frictionless;
    for (const ConstraintGroup& g : p.groups)
      if (g.kind != ConstraintKind::friction) frictionless.push_back(g);
    const Eigen::Index rows = static_cast<Eigen::Index>(frictionless.size());
    const Eigen::MatrixXd W = p.W.topLeftCorner(rows, rows);
    const Eigen::VectorXd violation = p.violation.head(rows);
    const Eigen::VectorXd exact = enumerated(W, violation, frictionless);
    const GaussSeidelSettings settings{.maxIterations = 100000, .tolerance = 1e-13};
    Eigen::VectorXd pgs, nncg;
    EXPECT_TRUE(solveProjectedGaussSeidel(W, violation, frictionless, settings, pgs).converged);
    EXPECT_TRUE(solveNonsmoothConjugateGradient(W, violation, frictionless, settings, nncg).converged);
    const double scale = 1 + exact.norm();
    EXPECT_LT((pgs - exact).norm(), 1e-7 * scale) << "seed " << seed;
    EXPECT_LT((nncg - exact).norm(), 1e-7 * scale) << "seed " << seed;
  }
}

TEST(ConstraintSolvers, ConjugateGradientSolutionsMeetTheirLaws) {
  // The random problems with friction: the conjugate gradient's solutions meet the laws as
  // Gauss-Seidel's do (it ends on a sweep).
  for (unsigned seed = 1; seed <= 50; ++seed) {
    SCOPED_TRACE(seed);
    const Problem p = randomProblem(seed);
    Eigen::VectorXd lambda;
    const ConstraintSolveReport report = solveNonsmoothConjugateGradient(
        p.W, p.violation, p.groups, {.maxIterations = 100000, .tolerance = 1e-12}, lambda);
    EXPECT_TRUE(report.converged) << report.iterations << " sweeps, error " << report.error;
    expectLawsHold(p, lambda, 1e-8);
  }
}

TEST(ConstraintSolvers, ConjugateGradientNeedsFewerSweepsOnAChain) {
  // A hanging chain of 40 points held to each other (bilateral rows between neighbours, W the
  // chain's Laplacian over unit masses): Gauss-Seidel propagates the load one link per sweep and
  // crawls; the conjugate gradient gets there in a fraction of the sweeps, to the same answer.
  const int links = 40;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(links, links);
  for (int i = 0; i < links; ++i) {
    H(i, i) = 1;
    if (i + 1 < links) H(i, i + 1) = -1;
  }
  const Eigen::MatrixXd W = 1e-4 * H * H.transpose();
  const Eigen::VectorXd violation = Eigen::VectorXd::Constant(links, -1e-4);
  std::vector<ConstraintGroup> groups;
  for (int i = 0; i < links; ++i)
    groups.push_back({ConstraintKind::bilateral, static_cast<std::size_t>(i), 1, 0});
  const GaussSeidelSettings settings{.maxIterations = 1000000, .tolerance = 1e-12};
  Eigen::VectorXd pgs, nncg;
  const ConstraintSolveReport a = solveProjectedGaussSeidel(W, violation, groups, settings, pgs);
  const ConstraintSolveReport b =
      solveNonsmoothConjugateGradient(W, violation, groups, settings, nncg);
  ASSERT_TRUE(a.converged);
  ASSERT_TRUE(b.converged);
  const Eigen::VectorXd exact = W.ldlt().solve(-violation);
  EXPECT_LT((nncg - exact).norm(), 1e-6 * exact.norm());
  EXPECT_LT((pgs - exact).norm(), 1e-6 * exact.norm());
  EXPECT_LT(b.iterations * 4, a.iterations) << "NNCG " << b.iterations << ", PGS " << a.iterations;
  std::printf("sweeps to 1e-12: projected Gauss-Seidel %d, conjugate gradient %d\n", a.iterations,
              b.iterations);
}

TEST(ConstraintSolvers, RegularizationSharesARedundantConstraint) {
  // The same bilateral row twice (W = c [1 1; 1 1], singular): with regularizationTerm r the
  // problem of W + r I has one solution, the two sharing the load, lambda = a / (2 c + r) each.
  const double c = 1e-3, a = 0.01, r = 1e-5;
  const Eigen::MatrixXd W = c * Eigen::MatrixXd::Ones(2, 2);
  const Eigen::VectorXd violation = Eigen::Vector2d(-a, -a);
  const std::vector<ConstraintGroup> rows{{ConstraintKind::bilateral, 0, 1, 0},
                                          {ConstraintKind::bilateral, 1, 1, 0}};
  const GaussSeidelSettings settings{.maxIterations = 100000, .tolerance = 1e-15, .regularization = r};
  Eigen::VectorXd pgs, nncg;
  solveProjectedGaussSeidel(W, violation, rows, settings, pgs);
  solveNonsmoothConjugateGradient(W, violation, rows, settings, nncg);
  for (const Eigen::VectorXd& lambda : {pgs, nncg}) {
    EXPECT_NEAR(lambda[0], a / (2 * c + r), 1e-9 * a / c);
    EXPECT_NEAR(lambda[1], a / (2 * c + r), 1e-9 * a / c);
  }
}

TEST(FrictionDisc, SlidesOppositeToTheResultingSlipWhateverTheBlock) {
  // An anisotropic block (a rigid body's corner: its rotation couples the two tangents): the
  // sliding force lies on the circle |lambda_t| = limit and points against the slip it leaves,
  // delta' = c + B lambda_t; sticking inside the disc cancels the slip.
  const Eigen::Matrix2d B = (Eigen::Matrix2d() << 3.0, 1.2, 1.2, 1.0).finished();
  for (const double angle : {0.0, 0.7, 2.0, 4.0}) {
    const Eigen::Vector2d c = 2.0 * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const Eigen::Vector2d t = solveFrictionDisc(B, c, 0.3);
    const Eigen::Vector2d slip = c + B * t;
    EXPECT_NEAR(t.norm(), 0.3, 1e-12);
    EXPECT_LT((t / t.norm() + slip / slip.norm()).norm(), 1e-9) << "angle " << angle;
    const Eigen::Vector2d stick = solveFrictionDisc(B, 0.01 * c, 0.3);
    EXPECT_LT((0.01 * c + B * stick).norm(), 1e-14);
  }
}

}  // namespace
}  // namespace stroma::test
