// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Link.h"
#include "linalg/AssembledMatrix.h"
#include "simulation/Solvers.h"

namespace stroma {

class DependentDofs;

/// Conjugate gradient on (m M + b B + k K) x = rhs (SOFA's CGLinearSolver). The default
/// template, GraphScattered, is matrix-free: each product goes through the force fields'
/// addDForce and the masses. A CompressedRowSparseMatrix template assembles the matrix once per
/// solve and iterates on it, optionally preconditioned by its diagonal (Jacobi). Stops when ||r||
/// <= tolerance ||rhs||, after `iterations`, or when a denominator falls below `threshold` (a
/// positive p.Ap below it is the scene's own stop and counts as converged for the ODE solver; a
/// non-positive one is a breakdown); a stop without convergence is reported (a warning the first time, and the count at the end of the run;
/// a residual that ended above the right-hand side's norm is said to have grown). The ODE solver
/// decides from the returned residual whether the stop is a divergence (its maxLinearResidual).
/// The matrix-free template calls the DependentDofs hooks of its system's projective
/// constraints (DependentDofs.h: the T-nodes of a multiresolution grid, seed 001 Algorithm 1)
/// around each product.
class CGLinearSolver final : public LinearSolver {
 public:
  Data<int> d_iterations{this, "iterations", 25, "Maximum number of iterations.", {.min = 1.0}};
  Data<double> d_tolerance{
      this, "tolerance", 1e-5, "Relative residual ||r|| / ||rhs|| at which to stop.", {.min = 0.0}};
  Data<double> d_threshold{this,
                           "threshold",
                           1e-5,
                           "Smallest denominator (p.Ap or r.r) before the iteration is "
                           "considered broken down.",
                           {.min = 0.0}};
  Data<bool> d_warmStart{this, "warmStart", false,
                         "Start from the previous solution instead of zero."};
  Data<bool> d_jacobiPreconditioner{this, "jacobiPreconditioner", false,
                                    "Precondition with the diagonal (assembled templates only; "
                                    "a warning says so for GraphScattered)."};
  Data<bool> d_verbose{this, "verbose", false, "Report every solve."};
  Data<int> d_maxIter{this,
                      "maxIter",
                      25,
                      "SOFA's former name of iterations (used when iterations is not given).",
                      {.min = 1.0}};
  Data<double> d_smallDenominatorThreshold{this,
                                           "smallDenominatorThreshold",
                                           1e-5,
                                           "SOFA's former name of threshold (used when "
                                           "threshold is not given).",
                                           {.min = 0.0}};
  Link<Base> l_linearSystem{this, "linearSystem",
                            "SOFA option, accepted: Stroma assembles the system itself."};
  Data<int> d_lastIterations{
      this, "lastIterations", 0, "Iterations of the last solve.", {.output = true}};
  Data<double> d_lastResidual{
      this, "lastResidual", 0.0, "Relative residual of the last solve.", {.output = true}};

  void init() override;
  LinearSolveReport solve(MechanicalOperations& mop, const MechanicalParams& mp, VecId x,
                          VecId rhs) override;
  void cleanup() override;

 private:
  LinearSolveReport solveMatrixFree(MechanicalOperations& mop, const MechanicalParams& mp, VecId x,
                                    VecId rhs);
  LinearSolveReport solveAssembled(MechanicalOperations& mop, const MechanicalParams& mp, VecId x,
                                   VecId rhs);
  void report(const LinearSolveReport& r);

  AssembledMatrix m_matrix;
  bool m_assembled = false;  // the template is an assembled matrix (set at init)
  std::vector<DependentDofs*> m_dependent;  // the T-node hooks of the last solve
  long long m_unconverged = 0;
  /// Why the last solve stopped short: p.Ap below `threshold` (or not finite), or not.
  bool m_brokeDown = false;
  double m_lastDenominator = 0;
  long long m_solves = 0;
};

}  // namespace stroma
