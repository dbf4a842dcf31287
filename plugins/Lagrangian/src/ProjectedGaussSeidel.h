// SPDX-License-Identifier: MIT
// The constraint problem of Constraints.h solved by projected Gauss-Seidel over the groups of
// rows (Jean 1999, "The non-smooth contact dynamics method", CMAME 177; Duriez et al. 2006,
// "Realistic haptic rendering of interacting deformable objects in virtual environments", IEEE
// TVCG 12, for the compliance formulation SOFA uses): each group in turn is solved with the
// others' multipliers fixed,
//   bilateral:  lambda += -delta / W_rr,
//   unilateral: lambda = max(0, lambda - delta / W_rr),
//   friction:   the normal row as unilateral, then the tangent pair by its 2 x 2 block of W:
//               sticking (delta_t = 0) when that force is inside the disc |lambda_t| <= mu
//               lambda_n, else sliding (solveFrictionDisc: on the circle, opposite to the slip
//               that results; projecting the sticking force onto the disc instead turns the
//               friction away from the slip when the block is not isotropic, as at the corner
//               of a rigid body, and a sliding box then yaws and brakes too little),
// each change scaled by `sor` (over-relaxation), until no row's displacement W_rr dlambda_r
// moves more than `tolerance` in a sweep.
#pragma once

#include <Eigen/Core>
#include <span>

#include "simulation/Constraints.h"

namespace stroma::lagrangian {

struct GaussSeidelSettings {
  int maxIterations = 1000;
  double tolerance = 1e-3;  ///< largest displacement change W_rr |dlambda_r| of a converged sweep
  double sor = 1.0;
  /// When >= 0, every friction group uses this coefficient (LCPConstraintSolver's `mu`).
  double muOverride = -1;
  /// Added to W's diagonal (a compliance, m/N): the problem solved is that of W + r I.
  double regularization = 0;
};

/// Coulomb's law for one contact's tangent pair with the rest fixed: the post-slip is
/// delta' = c + B lambda_t (B the pair's 2 x 2 block of W, c the slip at lambda_t = 0); returns
/// the sticking lambda_t = -B^-1 c when |lambda_t| <= limit (= mu lambda_n), else the lambda_t
/// on the circle |lambda_t| = limit opposite to delta' (maximal dissipation).
Eigen::Vector2d solveFrictionDisc(const Eigen::Matrix2d& B, const Eigen::Vector2d& c, double limit);

/// One sweep over the groups (in reverse order when `backward`), each solved with the others
/// fixed; lambda and delta = violation + W lambda are updated. Returns the largest displacement
/// change W_rr |dlambda_r|.
double gaussSeidelSweep(const Eigen::MatrixXd& W, std::span<const ConstraintGroup> groups,
                        const GaussSeidelSettings& settings, Eigen::VectorXd& lambda,
                        Eigen::VectorXd& delta, bool backward = false);

/// The same problem by the nonsmooth nonlinear conjugate gradient (SOFA's NNCGConstraintSolver):
/// the changes of symmetric sweeps (forward then backward) taken as (minus) gradients and
/// combined with a Fletcher-Reeves momentum, restarted when it grows. Converges in far fewer
/// sweeps where Gauss-Seidel crawls (stacks, long chains); ends on a sweep, so that its result
/// meets the laws as projected Gauss-Seidel's does. `iterations` counts sweeps (two per step).
ConstraintSolveReport solveNonsmoothConjugateGradient(const Eigen::MatrixXd& W,
                                                      const Eigen::VectorXd& violation,
                                                      std::span<const ConstraintGroup> groups,
                                                      const GaussSeidelSettings& settings,
                                                      Eigen::VectorXd& lambda);

/// Solves delta = violation + W lambda with each group's law; `lambda` is the start (warm start)
/// and the result.
ConstraintSolveReport solveProjectedGaussSeidel(const Eigen::MatrixXd& W,
                                                const Eigen::VectorXd& violation,
                                                std::span<const ConstraintGroup> groups,
                                                const GaussSeidelSettings& settings,
                                                Eigen::VectorXd& lambda);

}  // namespace stroma::lagrangian
