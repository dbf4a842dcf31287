// SPDX-License-Identifier: MIT
#include "ProjectedGaussSeidel.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace stroma::lagrangian {

Eigen::Vector2d solveFrictionDisc(const Eigen::Matrix2d& B, const Eigen::Vector2d& c, double limit) {
  if (!(limit > 0)) return Eigen::Vector2d::Zero();
  const double det = B.determinant();
  if (det > 0) {
    const Eigen::Vector2d stick = -B.inverse() * c;
    if (stick.norm() <= limit) return stick;
  }
  // Sliding: lambda_t = -k delta', delta' = c + B lambda_t, so lambda_t(k) = -k (I + k B)^-1 c,
  // whose length grows with k from 0 (to |B^-1 c| > limit): bisection on log k, then one exact
  // rescale onto the circle.
  const double cn = c.norm();
  if (!(cn > 0)) return Eigen::Vector2d::Zero();
  auto at = [&](double k) -> Eigen::Vector2d {
    const Eigen::Matrix2d A = Eigen::Matrix2d::Identity() + k * B;
    return -k * (A.inverse() * c);
  };
  double low = 0, high = limit / cn;  // k = limit / |c| is the answer for B = 0
  while (at(high).norm() < limit && high < 1e300) {
    low = high;
    high *= 4;
  }
  for (int i = 0; i < 100 && high - low > 1e-15 * high; ++i) {
    const double mid = low > 0 ? std::sqrt(low * high) : 0.5 * high;
    (at(mid).norm() < limit ? low : high) = mid;
  }
  const Eigen::Vector2d t = at(high);
  const double n = t.norm();
  return n > 0 ? Eigen::Vector2d(t * (limit / n)) : t;
}

ConstraintSolveReport solveProjectedGaussSeidel(const Eigen::MatrixXd& W,
                                                const Eigen::VectorXd& violation,
                                                std::span<const ConstraintGroup> groups,
                                                const GaussSeidelSettings& settings,
                                                Eigen::VectorXd& lambda) {
  ConstraintSolveReport report;
  const Eigen::Index n = violation.size();
  if (lambda.size() != n) lambda = Eigen::VectorXd::Zero(n);
  // delta = violation + W lambda, kept up to date as lambda changes.
  Eigen::VectorXd delta = violation + W * lambda;
  auto change = [&](Eigen::Index r, double dl, double& largest) {
    if (dl == 0) return;
    lambda[r] += dl;
    delta += W.col(r) * dl;
    largest = std::max(largest, std::abs(W(r, r) * dl));
  };
  report.converged = n == 0;
  for (int it = 0; it < settings.maxIterations && n > 0; ++it) {
    double largest = 0;
    for (const ConstraintGroup& g : groups) {
      const auto r = static_cast<Eigen::Index>(g.firstRow);
      const double wrr = W(r, r);
      if (!(wrr > 0)) continue;  // a row nothing can move: left at zero
      switch (g.kind) {
        case ConstraintKind::bilateral:
          change(r, -settings.sor * delta[r] / wrr, largest);
          break;
        case ConstraintKind::unilateral: {
          const double target = std::max(0.0, lambda[r] - delta[r] / wrr);
          change(r, settings.sor * (target - lambda[r]), largest);
          break;
        }
        case ConstraintKind::friction: {
          const double mu = settings.muOverride >= 0 ? settings.muOverride : g.mu;
          const double normal = std::max(0.0, lambda[r] - delta[r] / wrr);
          change(r, settings.sor * (normal - lambda[r]), largest);
          // The tangent pair: Coulomb's law on its 2 x 2 block of W with the others fixed.
          const Eigen::Matrix2d block = W.block<2, 2>(r + 1, r + 1);
          const Eigen::Vector2d old(lambda[r + 1], lambda[r + 2]);
          const Eigen::Vector2d d(delta[r + 1], delta[r + 2]);
          const Eigen::Vector2d t = solveFrictionDisc(block, d - block * old, mu * lambda[r]);
          change(r + 1, settings.sor * (t[0] - lambda[r + 1]), largest);
          change(r + 2, settings.sor * (t[1] - lambda[r + 2]), largest);
          break;
        }
      }
    }
    report.iterations = it + 1;
    report.error = largest;
    if (largest <= settings.tolerance) {
      report.converged = true;
      break;
    }
  }
  return report;
}

}  // namespace stroma::lagrangian
