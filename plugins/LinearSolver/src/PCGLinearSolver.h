// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "core/Link.h"
#include "simulation/Solvers.h"

namespace stroma {

/// Preconditioned conjugate gradient (SOFA's PCGLinearSolver): matrix-free CG on
/// A = m M + b B + k K (products through the force fields, as CGLinearSolver's GraphScattered
/// template), preconditioned by another linear solver P ~ A^-1, the `preconditioner` link
/// (usually a direct solver: SparseLDLSolver). Every `update_step` solves the preconditioner
/// solves with the current matrix (it assembles and factorizes); in between it reuses its last
/// factorization (LinearSolver::solveWithLastMatrix), so that a factorization a few steps old
/// still makes CG converge in a few iterations. With update_step = 1 the preconditioner is
/// exact and CG stops after one iteration; the factorization stays available to the
/// constraint corrections linked to the preconditioner.
///
/// As SOFA, CG starts from x = 0 and stops when r.z <= tolerance b.b (z = P r: the residual in
/// the preconditioner's norm over the squared norm of the right-hand side) or after
/// `iterations`. Without a preconditioner (none linked, or use_precond false) it is plain
/// matrix-free CG with that test. An unconverged solve is reported: a warning the first time,
/// the count at the end of the run.
class PCGLinearSolver final : public LinearSolver {
 public:
  Data<int> d_iterations{this, "iterations", 25, "Maximum number of iterations.", {.min = 1.0}};
  Data<double> d_tolerance{this,
                           "tolerance",
                           1e-5,
                           "Stop when r.(P r) <= tolerance b.b (SOFA's test: a ratio of squared "
                           "norms, r the residual, P the preconditioner, b the right-hand side).",
                           {.min = 0.0}};
  Data<bool> d_usePrecond{this, "use_precond", true, "Use the preconditioner."};
  Link<LinearSolver> l_preconditioner{this, "preconditioner",
                                      "The linear solver that preconditions CG (SparseLDLSolver, "
                                      "...)."};
  Data<std::string> d_preconditioners{this, "preconditioners", "",
                                      "SOFA's older name of the preconditioner link: the name of "
                                      "a linear solver in this node."};
  Data<int> d_updateStep{this,
                         "update_step",
                         1,
                         "Solves between two refreshes of the preconditioner (its matrix "
                         "assembled and factorized anew).",
                         {.min = 1.0}};
  Data<bool> d_buildPrecond{this, "build_precond", true,
                            "Refresh the preconditioner every update_step solves; false: only at "
                            "the first solve."};
  Link<Base> l_linearSystem{this, "linearSystem",
                            "SOFA option, accepted: products go through the force fields."};
  Data<int> d_lastIterations{
      this, "lastIterations", 0, "Iterations of the last solve.", {.output = true}};
  Data<double> d_lastResidual{this,
                              "lastResidual",
                              0.0,
                              "Relative residual ||r|| / ||b|| of the last solve.",
                              {.output = true}};
  Data<int> d_refreshes{this, "refreshes", 0, "Refreshes of the preconditioner so far.",
                        {.output = true}};

  void init() override;
  LinearSolveReport solve(MechanicalOperations& mop, const MechanicalParams& mp, VecId x,
                          VecId rhs) override;
  void cleanup() override;

 private:
  /// z = P r, refreshing P when it is due; false when the preconditioner failed.
  bool precondition(MechanicalOperations& mop, const MechanicalParams& mp, VecId z, VecId r);

  LinearSolver* m_preconditioner = nullptr;
  int m_solvesSinceRefresh = 0;
  bool m_refreshed = false;  ///< the preconditioner was refreshed at least once
  long long m_solves = 0, m_unconverged = 0;
};

}  // namespace stroma
