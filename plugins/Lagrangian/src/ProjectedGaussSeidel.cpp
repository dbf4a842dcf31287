// SPDX-License-Identifier: MIT
#include "ProjectedGaussSeidel.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace stroma::lagrangian {

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
          // The tangent pair: sticking target from its 2 x 2 block, then onto the cone.
          const Eigen::Matrix2d block = W.block<2, 2>(r + 1, r + 1);
          Eigen::Vector2d t(lambda[r + 1], lambda[r + 2]);
          const Eigen::Vector2d d(delta[r + 1], delta[r + 2]);
          if (block.determinant() > 0) t -= block.inverse() * d;
          const double limit = mu * lambda[r];
          if (t.norm() > limit) t *= limit > 0 ? limit / t.norm() : 0.0;
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
