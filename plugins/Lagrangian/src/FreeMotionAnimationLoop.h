// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/Data.h"
#include "core/Link.h"
#include "simulation/AnimationLoop.h"
#include "simulation/Constraints.h"

namespace stroma {

class MechanicalOperations;
class OdeSolver;

/// SOFA's FreeMotionAnimationLoop, in the root node: each step (Constraints.h)
///   1. behavior models; collision (when the root holds a collision pipeline), on the
///      positions of the step's start (as SOFA): a constraint response
///      (FrictionContactConstraint) turns the contacts into constraints;
///   2. free motion: every ODE solver integrates its states without the Lagrangian
///      constraints;
///   3. every Lagrangian constraint of the scene gives its rows and violations (at the free
///      positions: a contact's gap is measured there, with the primitives and weights of its
///      detection); the rows are
///      carried to each solver's independent states through the mappings (H J);
///   4. each solver's constraint correction adds its compliance to W;
///   5. the constraint solver (`constraintSolver`, else the one in the root) finds the
///      multipliers; each constraint receives its own;
///   6. each correction moves its states (positions and velocities), the mapped states follow.
/// A step with no constraint row is the free motion alone.
class FreeMotionAnimationLoop final : public AnimationLoop {
 public:
  Link<BaseConstraintSolver> l_constraintSolver{this, "constraintSolver",
                                                "The constraint solver (default: the one in "
                                                "this node)."};
  Data<int> d_constraintRows{this, "constraintRows", 0,
                             "Output: constraint rows of the last step.", {.output = true}};

  FreeMotionAnimationLoop();
  ~FreeMotionAnimationLoop() override;

  void init() override;
  void step(Node& root, double dt, Timing& timing) override;
  bool solvesConstraints() const override { return true; }

 private:
  struct SolverSystem;  // one ODE solver's operations, rows and correction this step
  void collectSolvers(Node& node);
  void updateBehaviorModels(Node& node, double dt);
  bool solveConstraints(Node& root, double dt, Timing& timing);
  void storeConstraintForces(std::span<SolverSystem> systems);

  BaseConstraintSolver* m_solver = nullptr;
  std::vector<std::pair<Node*, OdeSolver*>> m_solvers;
  std::vector<BaseLagrangianConstraint*> m_constraints;
  std::vector<std::size_t> m_firstRows;
  ConstraintRows m_rows;
  ConstraintProblem m_problem;
  Eigen::VectorXd m_force;
  std::vector<BaseMechanicalState*> m_forcedBefore, m_forcedNow;
  std::vector<SolverSystem> m_systems;  // the first ones used this step
  std::vector<Eigen::Triplet<double>> m_triplets, m_systemTriplets;
  std::vector<char> m_fixed;
};

}  // namespace stroma
