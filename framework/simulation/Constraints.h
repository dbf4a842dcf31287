// SPDX-License-Identifier: MIT
// Lagrangian constraints (SOFA's order, DESIGN.md section 8): each step, after the free motion of
// every solver and the collision on the free positions, the constraints give rows H (the
// gradients of their violations, on any states, mapped ones included), the rows are carried to
// each solver's independent states through the mappings (H_s = H_state J), each solver's
// constraint correction gives its compliance W_s = H_s C_s H_s^T, a constraint solver finds the
// multipliers lambda of
//     delta = delta_free + W lambda,   W = sum_s W_s,
// with each group's law (bilateral: delta = 0; unilateral: delta >= 0, lambda >= 0, delta lambda
// = 0; Coulomb friction: that along the normal row, |lambda_t| <= mu lambda_n on the two tangent
// rows, sticking (delta_t = 0) inside the cone), and each correction moves its states by
// C_s H_s^T lambda (positions) and C_s H_s^T lambda / positionPerVelocity (velocities).
//
// Units: a violation is a length (the gap along the normal, a tangential slip over the step, a
// distance between two held points), a multiplier a force (N), W a compliance (m/N).
#pragma once

#include <Eigen/Core>
#include <array>
#include <Eigen/SparseCore>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "core/Base.h"
#include "core/Types.h"
#include "simulation/VecId.h"

namespace stroma {

class BaseMechanicalState;
class MechanicalOperations;

/// How the constraint solver treats a group of rows.
enum class ConstraintKind {
  bilateral,   ///< one row, delta = 0, lambda free
  unilateral,  ///< one row, delta >= 0, lambda >= 0, complementary
  friction,    ///< three rows (normal, tangent, tangent): unilateral normal, Coulomb cone mu
};

struct ConstraintGroup {
  ConstraintKind kind = ConstraintKind::bilateral;
  std::size_t firstRow = 0;
  int rowCount = 1;
  double mu = 0;  ///< friction coefficient (friction groups)
};

/// The rows of one step, built by the constraints: groups of rows, each row's violation at the
/// free positions, and its entries on the states (row, dof of the state's matrix space, value).
class ConstraintRows {
 public:
  struct Entry {
    std::size_t row;
    std::size_t dof;  ///< index in the state's matrix space (point * deriv size + component)
    double value;
  };

  /// Starts a group of rows; returns the index of its first row. `violations` has its rows'
  /// violations (rowCount values).
  std::size_t addGroup(ConstraintKind kind, std::span<const double> violations, double mu = 0);
  /// H(row, dof of `state`) += value.
  void add(std::size_t row, const BaseMechanicalState* state, std::size_t dof, double value);

  std::size_t rowCount() const { return m_violations.size(); }
  const std::vector<ConstraintGroup>& groups() const { return m_groups; }
  const std::vector<double>& violations() const { return m_violations; }
  /// The states that have entries, and each one's entries.
  std::span<const BaseMechanicalState* const> states() const { return {m_states.data(), m_usedStates}; }
  const std::vector<Entry>& entriesOf(std::size_t stateIndex) const { return m_entries[stateIndex]; }

  /// Empties it for the next step, keeping its storage.
  void clear();

 private:
  std::vector<ConstraintGroup> m_groups;
  std::vector<double> m_violations;
  std::vector<const BaseMechanicalState*> m_states;
  std::vector<std::vector<Entry>> m_entries;  // per state
  std::size_t m_usedStates = 0;
};

/// An orthonormal frame (n, t1, t2) completing the unit normal n (t1, t2 the tangents of a
/// contact's friction rows).
std::array<Vec3d, 3> contactFrame(const Vec3d& n);

/// Adds the group of one contact with the frame (n, t1, t2): with mu > 0 a friction group of
/// three rows (violations gap, t1.slip, t2.slip; slip the tangential displacement over the
/// step), else the unilateral normal row alone. Returns its first row; `rowCount` gets 3 or 1.
std::size_t addContactGroup(ConstraintRows& rows, const std::array<Vec3d, 3>& frame, double gap,
                            const Vec3d& slip, double mu, int& rowCount);

/// A constraint with Lagrange multipliers: a contact response, points held together, a point
/// on a plane... Any component of the scene; FreeMotionAnimationLoop asks them all.
class BaseLagrangianConstraint : public Base {
 public:
  /// Adds its rows at the free positions (VecId::position() after the free motion), with their
  /// violations. `dt` is the step's length (a slip over the step is a tangential violation).
  virtual void buildConstraintRows(ConstraintRows& rows, double dt) = 0;
  /// The multipliers of its rows after the solve (rows [first, first + count) of what it added,
  /// in the order it added them).
  virtual void storeMultipliers(std::span<const double> lambda) { (void)lambda; }
};

/// How a solver's state answers a constant force applied over a step: the states move by
///   dx = positionFactor A^-1 f,   dv = velocityFactor A^-1 f,
/// A = matrix.mFactor M + matrix.bFactor B + matrix.kFactor K (the solver's system): implicit
/// Euler h^2 and h with its matrix, symplectic Euler h^2 and h with M, static 1 and 0 with -K.
struct ConstraintResponse {
  MechanicalParams matrix;
  double positionFactor = 0;
  double velocityFactor = 0;
};

/// The compliance of one solver's states: SOFA's constraint corrections, in the solver's node.
class BaseConstraintCorrection : public Base {
 public:
  /// W += H C H^T for the rows H (rows x system size of `mop`, already carried to its
  /// independent states and projected by its fixed dofs).
  virtual void addCompliance(MechanicalOperations& mop, const ConstraintResponse& response,
                             const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                             Eigen::MatrixXd& W) = 0;
  /// Moves positions by positionFactor A^-1 H^T lambda and velocities by velocityFactor A^-1
  /// H^T lambda.
  virtual void applyCorrection(MechanicalOperations& mop, const ConstraintResponse& response,
                               const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                               const Eigen::VectorXd& lambda) = 0;
};

struct ConstraintSolveReport {
  bool converged = true;
  int iterations = 0;
  double error = 0;  ///< the solver's measure of the remaining violation of the laws
};

/// One step's constraint problem and its solution: delta = violation + W lambda.
struct ConstraintProblem {
  Eigen::MatrixXd W;
  Eigen::VectorXd violation;
  std::vector<ConstraintGroup> groups;
  Eigen::VectorXd lambda;
};

/// How far a solution is from its laws (each one 0 for an exact solution; lengths in the
/// violations' unit, forces in the multipliers'):
struct ConstraintLawResiduals {
  double negativeForce = 0;    ///< largest -lambda_n (unilateral and friction normal rows)
  double penetration = 0;      ///< largest -delta_n
  double complementarity = 0;  ///< largest |lambda_n delta_n|
  double outsideCone = 0;      ///< largest |lambda_t| - mu lambda_n
  double slipWhileInside = 0;  ///< largest |delta_t| where |lambda_t| < mu lambda_n (sticking)
  double bilateral = 0;        ///< largest |delta| of bilateral rows
};
/// Measures them for `problem` (independent of the solver that produced lambda).
ConstraintLawResiduals lawResiduals(const ConstraintProblem& problem, double coneSlack = 1e-9);

/// Finds lambda for delta = violation + W lambda with each group's law.
class BaseConstraintSolver : public Base {
 public:
  virtual ConstraintSolveReport solve(const Eigen::MatrixXd& W, const Eigen::VectorXd& violation,
                                      std::span<const ConstraintGroup> groups,
                                      Eigen::VectorXd& lambda) = 0;

  /// The last problem the animation loop gave it, with its solution (nullptr before any).
  const ConstraintProblem* lastProblem() const { return m_lastProblem; }
  void setLastProblem(const ConstraintProblem* problem) { m_lastProblem = problem; }

 private:
  const ConstraintProblem* m_lastProblem = nullptr;
};

}  // namespace stroma
