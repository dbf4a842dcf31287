// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

#include "core/Base.h"
#include "core/Node.h"
#include "simulation/VecId.h"

namespace stroma {

class MechanicalOperations;
class Timing;

/// Integrates the states of its node's subtree over one time step (subtrees with their own
/// solver excluded), through MechanicalOperations only.
struct ConstraintResponse;

class OdeSolver : public Base {
 public:
  OdeSolver();
  ~OdeSolver() override;
  virtual void solve(MechanicalOperations& mop, double dt) = 0;

  /// The operations on the system of its node (`node`, the solver's own) for a step of `dt`,
  /// kept from step to step so that a warm step allocates nothing (MechanicalOperations::reset);
  /// valid until the next call.
  MechanicalOperations& operations(Node& node, Timing& timing, double dt);

  /// How its states answer a force held over a step of `dt` (Constraints.h), for the
  /// constraint corrections; false when the scheme has no such answer.
  virtual bool constraintResponse(double dt, ConstraintResponse& response) const {
    (void)dt;
    (void)response;
    return false;
  }

  /// Called by the animation loop when the solver's node has no mechanical state at or below
  /// it: warns once, since such a solver integrates nothing (a misplaced solver or state).
  void reportNoState() {
    if (m_reportedNoState) return;
    m_reportedNoState = true;
    msgWarning("no mechanical state in " + (node() ? node()->path() : std::string("its node")) +
               " or below: this solver integrates nothing (put it in the node of the "
               "MechanicalObject it should move, or above it)");
  }

 private:
  bool m_reportedNoState = false;
  std::unique_ptr<MechanicalOperations> m_operations;
};

/// Outcome of a linear solve, reported to the log by the solver and returned to the caller.
struct LinearSolveReport {
  bool converged = true;
  int iterations = 0;
  double residual = 0;  ///< final residual norm, relative to the right-hand side's
};

/// Solves (m M + b B + k K) x = rhs on the states of a MechanicalOperations, with the factors of
/// `mp`, projected by the constraints.
class LinearSolver : public Base {
 public:
  virtual LinearSolveReport solve(MechanicalOperations& mop, const MechanicalParams& mp, VecId x,
                                  VecId rhs) = 0;
  /// Solves again with the matrix of its last solve (a direct solver keeps its factorization:
  /// the constraint corrections solve once per constraint row). False when it cannot; the
  /// caller then calls solve().
  virtual bool solveWithLastMatrix(MechanicalOperations& mop, VecId x, VecId rhs) {
    (void)mop;
    (void)x;
    (void)rhs;
    return false;
  }
  /// W += factor J A^-1 J^T with the matrix of its last solve (SOFA's addJMInvJt): J is
  /// (rows x systemSize()), W (rows x rows). A direct solver does it from its factors without a
  /// solve per row of J (the compliance of the constraint corrections). False when it cannot;
  /// the caller then solves row by row.
  virtual bool addJMInvJt(MechanicalOperations& mop,
                          const Eigen::SparseMatrix<double, Eigen::RowMajor>& J, double factor,
                          Eigen::MatrixXd& W) {
    (void)mop;
    (void)J;
    (void)factor;
    (void)W;
    return false;
  }
};

}  // namespace stroma
