// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "linalg/AssembledMatrix.h"
#include "simulation/VecId.h"

namespace stroma {

class Base;
class BaseForceField;
class BaseMapping;
class BaseMass;
class BaseMechanicalState;
class BaseProjectiveConstraint;
class Node;
class StateOffsets;
class Timing;

/// The operations an ODE or linear solver performs on the whole mechanical system of its
/// node's subtree (sub-nodes with their own solver excluded): vector algebra over every
/// independent state, forces and their derivatives with mapped states handled through the
/// mappings (J and J^T), projections by the constraints, and the assembled matrix
/// m M + b B + k K with the mapped contributions J^T K J. Solvers use nothing else, so that they
/// work for any mix of states, force fields, masses, constraints and mappings.
///
/// "Independent" states are those no mechanical mapping outputs; they are the unknowns.
///
/// Interaction force fields may act on a state of this solver and one outside it: a spring to
/// another body, or a contact response, which the collision pipeline puts in the nearest common
/// ancestor of the two models' nodes (so it is collected from this solver's ancestors too). The
/// states outside are "foreign": this solver's temporary vectors exist on them, zeroed, so
/// that their increments read as zero (they are held fixed during this solve), and they are
/// never integrated.
class MechanicalOperations {
 public:
  /// `dt`: the duration of the step being solved (0 when unknown); the constraints impose
  /// positions and velocities at its end (see projectPosition).
  MechanicalOperations(Node& solverNode, Timing& timing, double dt = 0);
  ~MechanicalOperations();
  /// Starts a new step with the same operations object (OdeSolver::operations keeps one per
  /// solver): temporaries released, the time step and timing taken, and the states, force
  /// fields, masses, constraints and mappings collected again only when the graph changed (an
  /// object added, removed, (de)activated or invalid, a state resized, a mapping relinked). A
  /// warm step thus allocates nothing here.
  void reset(Node& solverNode, Timing& timing, double dt);
  MechanicalOperations(const MechanicalOperations&) = delete;
  MechanicalOperations& operator=(const MechanicalOperations&) = delete;

  Node& node() const { return *m_node; }
  Timing& timing() const { return *m_timing; }
  /// Simulation time at the start of the step.
  double time() const;
  /// Simulation time at the end of the step: time() + dt.
  double endTime() const { return time() + m_dt; }

  const std::vector<BaseMechanicalState*>& independentStates() const { return m_independent; }
  const std::vector<BaseMass*>& masses() const { return m_masses; }
  const std::vector<BaseProjectiveConstraint*>& constraints() const { return m_constraints; }
  bool hasState() const { return !m_independent.empty(); }
  /// Per row of the assembled system, 1 when a projective constraint fixes it (the rows that
  /// assemble() replaces by identity rows).
  void fixedGlobalRows(std::vector<char>& fixed) const;

  /// Temporary vectors on every state (independent and mapped), zeroed. Freed with freeVec,
  /// at the next reset, or when the operations end (the states keep their storage).
  VecId allocDeriv();
  VecId allocCoord();
  void freeVec(VecId v);

  /// v = a + b f on the independent states (see BaseMechanicalState::vOp).
  void vOp(VecId v, VecId a, VecId b = VecId::null(), double f = 1.0);
  double dot(VecId a, VecId b) const;
  double norm(VecId a) const;

  /// f = every force at (mp.x, mp.v), mapped forces included through J^T.
  void computeForce(const MechanicalParams& mp, VecId f);
  /// out = (mp.mFactor M + mp.bFactor B + mp.kFactor K) dx, mapped parts through J and J^T.
  void computeMBKdx(const MechanicalParams& mp, VecId out, VecId dx);
  /// a = M^-1 f, for lumped masses. Returns false (after an error naming the state) when a
  /// state has no mass or a non-diagonal one.
  bool accFromF(VecId a, VecId f);

  void projectResponse(VecId dx);
  /// Impose the constrained positions and velocities of the end of the step (endTime()): the
  /// solvers call them on the integrated state.
  void projectPosition(VecId x);
  void projectVelocity(VecId v);
  /// Positions and velocities of the mapped states from the independent ones.
  void propagate(VecId x, VecId v);
  /// Increments of the mapped states from those of the independent ones (dx -> J dx), through
  /// the mappings that lead to a force field or a mass only (computeForce and computeMBKdx
  /// go back through those same ones).
  void propagateDx(VecId dx);

  /// Rows of the assembled system: the independent states' deriv numbers, in order.
  std::size_t systemSize() const { return m_systemSize; }
  /// A = mp.mFactor M + mp.bFactor B + mp.kFactor K, with the rows and columns of fixed
  /// degrees of freedom replaced by the identity.
  void assemble(const MechanicalParams& mp, AssembledMatrix& A);
  void gather(VecId v, Eigen::VectorXd& out) const;
  void scatter(const Eigen::VectorXd& in, VecId v);

  double potentialEnergy(const MechanicalParams& mp) const;
  double kineticEnergy() const;

  /// Reports NaN or infinity in `v` as an error of `reporter` (with the state, the index of the
  /// first non-finite vertex and the time at the end of the step, endTime()) and returns false.
  bool checkFinite(VecId v, const std::string& what, Base& reporter) const;
  /// The vertex where `v` is worst over the independent states: the first non-finite value, or
  /// else the largest absolute component. Divergence reports name it.
  struct WorstVertex {
    const BaseMechanicalState* state = nullptr;  ///< null when there is no state
    std::size_t index = 0;
    double value = 0;  ///< the largest absolute component (or the non-finite one)
  };
  WorstVertex worstVertex(VecId v) const;
  /// "vertex 12 of /root/Body/dofs (|velocity| component 3.2e+04)", `what` naming `v`.
  std::string describeWorstVertex(VecId v, const std::string& what) const;

  /// d(state's dofs) / d(system dofs): the selection of an independent state's rows, the
  /// product of the mapping Jacobians for a mapped one, zero for a state outside this system
  /// ((state matrixSize) x systemSize()).
  Eigen::SparseMatrix<double> totalJacobian(const BaseMechanicalState* state);
  /// Whether `state` is one of this solver's states (independent or mapped).
  bool contains(const BaseMechanicalState* state) const;
  /// Where an independent state's dofs start in the system (its totalJacobian is the identity
  /// there); false for a mapped state or one outside this system.
  bool independentOffset(const BaseMechanicalState* state, std::size_t& offset) const;

 private:
  void collectAll();
  void collect(Node& node, bool isSolverNode);
  /// Writes (or, with `compare`, checks against the last one) the fingerprint of what collect
  /// reads: every object of the subtree and of the ancestors, with validity, state sizes and
  /// mapping ends. Returns whether it is unchanged.
  bool fingerprint(Node& node, bool isSolverNode, std::size_t& at, bool compare);
  /// Forgets the temporaries, releasing them on the states when `onStates`.
  void freeTemporaries(bool onStates);
  void collectInteractions();
  void collectLoadedMappings();
  void clearOnAll(VecId v);

  Node* m_node;
  Timing* m_timing;
  double m_dt = 0;
  std::vector<BaseMechanicalState*> m_states;       // all, top-down
  std::vector<BaseMechanicalState*> m_independent;  // not outputs of a mechanical mapping
  std::vector<BaseMechanicalState*> m_foreign;      // acted on by its force fields, not its own
  std::vector<BaseForceField*> m_forceFields;       // masses included
  std::vector<BaseMass*> m_masses;
  std::vector<BaseProjectiveConstraint*> m_constraints;
  std::vector<BaseMapping*> m_mappings;  // mechanical ones, top-down
  std::vector<BaseMapping*> m_loadedMappings;  // those leading to a force field or mass
  std::vector<std::size_t> m_offsets;    // per independent state
  std::size_t m_systemSize = 0;
  std::vector<VecId> m_temporaries;
  std::vector<std::uintptr_t> m_fingerprint;          // of the graph at the last collection
  std::vector<const BaseMechanicalState*> m_loadedScratch;  // collectLoadedMappings' work
  std::vector<char> m_neededScratch;
  std::unique_ptr<StateOffsets> m_stateOffsets;  // of the independent states, for assembly
  std::vector<char> m_fixedScratch;              // assemble's fixed rows
  mutable std::vector<std::size_t> m_rowsScratch;  // fixedGlobalRows' rows of one constraint
  int m_nextCoord = VecId::kFirstTemporary;
  int m_nextDeriv = VecId::kFirstTemporary;
};

}  // namespace stroma
