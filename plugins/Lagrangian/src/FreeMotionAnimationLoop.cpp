// SPDX-License-Identifier: MIT
#include "FreeMotionAnimationLoop.h"

#include <algorithm>

#include "collision/CollisionPipeline.h"
#include "core/Node.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/MechanicalState.h"
#include "simulation/Solvers.h"
#include "simulation/Timing.h"

namespace stroma {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct FreeMotionAnimationLoop::SolverSystem {
  OdeSolver* solver = nullptr;
  MechanicalOperations* mop = nullptr;  // the solver's own (OdeSolver::operations)
  BaseConstraintCorrection* correction = nullptr;
  ConstraintResponse response;
  RowMatrix H;          // the rows on the system's dofs, fixed columns dropped
  RowMatrix forceRows;  // the same with every column, for the forces on the states
};

FreeMotionAnimationLoop::FreeMotionAnimationLoop() = default;
FreeMotionAnimationLoop::~FreeMotionAnimationLoop() = default;

void FreeMotionAnimationLoop::init() {
  if (node() && node()->parent())
    msgWarning("an animation loop acts from the root node only: move it to " +
               node()->root().path());
  m_solver = l_constraintSolver.get();
  if (!m_solver && node()) m_solver = node()->get<BaseConstraintSolver>();
  if (!m_solver)
    msgError("needs a constraint solver (GenericConstraintSolver, LCPConstraintSolver) in its "
             "node, or a 'constraintSolver' link",
             "constraintSolver");
}

void FreeMotionAnimationLoop::collectSolvers(Node& node) {
  if (!node.d_activated.value()) return;
  for (const auto& object : node.objects())  // not getAll: no list allocated per step
    if (auto* solver = dynamic_cast<OdeSolver*>(object.get()); solver && solver->isValid())
      m_solvers.push_back({&node, solver});
  for (const auto& child : node.children()) collectSolvers(*child);
}

namespace {

void collectConstraints(Node& node, std::vector<BaseLagrangianConstraint*>& out) {
  if (!node.d_activated.value()) return;
  for (const auto& o : node.objects())
    if (auto* c = dynamic_cast<BaseLagrangianConstraint*>(o.get()); c && c->isValid())
      out.push_back(c);
  for (const auto& child : node.children()) collectConstraints(*child, out);
}

// The correction of a solver's states: in its node, else in a node below it that has no solver
// of its own.
BaseConstraintCorrection* findCorrection(Node& node, bool isSolverNode) {
  if (!isSolverNode && node.get<OdeSolver>()) return nullptr;
  if (auto* c = node.get<BaseConstraintCorrection>()) return c;
  for (const auto& child : node.children())
    if (auto* c = findCorrection(*child, false)) return c;
  return nullptr;
}

}  // namespace

void FreeMotionAnimationLoop::updateBehaviorModels(Node& node, double dt) {
  for (const auto& object : node.objects())
    if (auto* model = dynamic_cast<BehaviorModel*>(object.get())) model->updatePosition(dt);
  for (const auto& child : node.children()) updateBehaviorModels(*child, dt);
}

void FreeMotionAnimationLoop::step(Node& root, double dt, Timing& timing) {
  {
    ScopedPhase phase(timing, "behaviorModels");
    updateBehaviorModels(root, dt);
  }
  // Collision on the positions of the step's start, as SOFA (its free motion writes separate
  // free positions): a body moving more than the alarm distance per step is still caught
  // before it passes through; the contacts' rows are then measured at the free positions.
  if (CollisionPhase* collision = root.get<CollisionPhase>(); collision && collision->isValid()) {
    ScopedPhase phase(timing, "collision");
    collision->computeCollisions(root, timing);
  }
  m_solvers.clear();
  collectSolvers(root);
  {
    ScopedPhase phase(timing, "freeMotion");
    for (auto& [node, solver] : m_solvers) {
      MechanicalOperations& mop = solver->operations(*node, timing, dt);
      if (!mop.hasState()) solver->reportNoState();
      mop.projectVelocity(VecId::velocity());
      solver->solve(mop, dt);
    }
  }
  {
    ScopedPhase phase(timing, "constraints");
    solveConstraints(root, dt, timing);
  }
  root.setTime(root.time() + dt);
}

bool FreeMotionAnimationLoop::solveConstraints(Node& root, double dt, Timing& timing) {
  m_rows.clear();
  m_constraints.clear();
  m_firstRows.clear();
  collectConstraints(root, m_constraints);
  for (BaseLagrangianConstraint* c : m_constraints) {
    m_firstRows.push_back(m_rows.rowCount());
    c->buildConstraintRows(m_rows, dt);
  }
  m_firstRows.push_back(m_rows.rowCount());
  const auto m = static_cast<Eigen::Index>(m_rows.rowCount());
  d_constraintRows.setValue(static_cast<int>(m));
  if (m == 0) {
    storeConstraintForces({});
    m_problem.W.resize(0, 0);
    m_problem.violation.resize(0);
    m_problem.lambda.resize(0);
    m_problem.groups.clear();
  }
  if (m == 0 || !m_solver) return true;

  // Each solver's rows, carried to its independent states, and its compliance.
  m_problem.W.setZero(m, m);
  // Kept from step to step with their storage (a warm step allocates less).
  std::vector<Eigen::Triplet<double>>& triplets = m_triplets;
  std::vector<Eigen::Triplet<double>>& systemTriplets = m_systemTriplets;
  std::size_t used = 0;
  for (auto& [node, solver] : m_solvers) {
    if (used == m_systems.size()) m_systems.emplace_back();
    SolverSystem& system = m_systems[used];
    system.correction = nullptr;
    system.solver = solver;
    system.mop = &solver->operations(*node, timing, dt);
    MechanicalOperations& mop = *system.mop;
    const auto n = static_cast<Eigen::Index>(mop.systemSize());
    system.H.resize(m, n);
    // Rows on an independent state go straight to its columns; rows on a mapped state are
    // carried through the product of its mappings' Jacobians.
    bool any = false;
    systemTriplets.clear();
    for (std::size_t s = 0; s < m_rows.states().size(); ++s) {
      const BaseMechanicalState* state = m_rows.states()[s];
      if (!mop.contains(state)) continue;
      any = true;
      std::size_t offset = 0;
      if (mop.independentOffset(state, offset)) {
        for (const ConstraintRows::Entry& e : m_rows.entriesOf(s))
          systemTriplets.emplace_back(static_cast<Eigen::Index>(e.row),
                                      static_cast<Eigen::Index>(offset + e.dof), e.value);
        continue;
      }
      triplets.clear();
      for (const ConstraintRows::Entry& e : m_rows.entriesOf(s))
        triplets.emplace_back(static_cast<Eigen::Index>(e.row), static_cast<Eigen::Index>(e.dof),
                              e.value);
      RowMatrix onState(m, static_cast<Eigen::Index>(state->matrixSize()));
      onState.setFromTriplets(triplets.begin(), triplets.end());
      const RowMatrix carried = onState * mop.totalJacobian(state);
      for (Eigen::Index r = 0; r < carried.outerSize(); ++r)
        for (RowMatrix::InnerIterator it(carried, r); it; ++it)
          systemTriplets.emplace_back(it.row(), it.col(), it.value());
    }
    system.H.setFromTriplets(systemTriplets.begin(), systemTriplets.end());
    if (!any) continue;
    // The forces on the states are H^T lambda with every column (an instrument moved by an
    // imposed motion feels its contacts); the compliance and the correction leave out the
    // columns of fixed dofs, which do not move. A solver whose rows are all on fixed dofs takes
    // no part in the solve.
    system.forceRows = system.H;
    std::vector<char>& fixed = m_fixed;
    mop.fixedGlobalRows(fixed);
    system.H.prune([&](Eigen::Index, Eigen::Index col, double) {
      return !fixed[static_cast<std::size_t>(col)];
    });
    if (system.H.nonZeros() > 0) {
      system.correction = findCorrection(*node, true);
      if (!system.correction) {
        msgError("the states of " + node->path() + " have constraint rows (contacts or "
                 "constraints) but no constraint correction: add UncoupledConstraintCorrection "
                 "or LinearSolverConstraintCorrection beside its solver " + solver->path(),
                 "constraintSolver");
        return false;
      }
      if (!solver->constraintResponse(dt, system.response)) {
        msgError(solver->path() + " (" + solver->className() + ") cannot answer constraint "
                 "forces (forward Euler moves positions with the old velocities): use "
                 "EulerImplicitSolver or symplectic EulerExplicitSolver",
                 "constraintSolver");
        return false;
      }
      system.correction->addCompliance(mop, system.response, system.H, m_problem.W);
    }
    ++used;
  }
  const std::span<SolverSystem> systems(m_systems.data(), used);

  m_problem.violation = Eigen::Map<const Eigen::VectorXd>(m_rows.violations().data(), m);
  m_problem.groups.assign(m_rows.groups().begin(), m_rows.groups().end());
  m_solver->solve(m_problem.W, m_problem.violation, m_problem.groups, m_problem.lambda);
  m_solver->setLastProblem(&m_problem);

  for (SolverSystem& system : systems)
    if (system.correction)
      system.correction->applyCorrection(*system.mop, system.response, system.H, m_problem.lambda);
  storeConstraintForces(systems);
  for (std::size_t c = 0; c < m_constraints.size(); ++c)
    m_constraints[c]->storeMultipliers(std::span<const double>(
        m_problem.lambda.data() + m_firstRows[c], m_firstRows[c + 1] - m_firstRows[c]));
  return true;
}

// Each state's constraintForce: the rows' entries on it times lambda (a mapped collision
// surface: the force at each contact point; an obstacle outside every solver: its reaction),
// and on the independent states of each solver H_s^T lambda, the forces of all the rows carried
// through the mappings (a rigid probe: the total force and torque, what a haptic device
// renders). States that had a force at the last step and none now are set to zero.
void FreeMotionAnimationLoop::storeConstraintForces(std::span<SolverSystem> systems) {
  const Eigen::VectorXd& lambda = m_problem.lambda;
  m_forcedNow.clear();
  for (std::size_t s = 0; s < m_rows.states().size(); ++s) {
    auto* state = const_cast<BaseMechanicalState*>(m_rows.states()[s]);
    m_force.setZero(static_cast<Eigen::Index>(state->matrixSize()));
    for (const ConstraintRows::Entry& e : m_rows.entriesOf(s))
      m_force[static_cast<Eigen::Index>(e.dof)] += e.value * lambda[static_cast<Eigen::Index>(e.row)];
    state->copyFromGlobal(VecId::constraintForce(), m_force, 0);
    m_forcedNow.push_back(state);
  }
  for (SolverSystem& system : systems) {
    m_force = system.forceRows.transpose() * lambda;
    system.mop->scatter(m_force, VecId::constraintForce());
    for (BaseMechanicalState* state : system.mop->independentStates()) m_forcedNow.push_back(state);
  }
  for (BaseMechanicalState* state : m_forcedBefore)
    if (std::find(m_forcedNow.begin(), m_forcedNow.end(), state) == m_forcedNow.end())
      state->vOp(VecId::constraintForce(), VecId::null(), VecId::null(), 0.0);
  std::swap(m_forcedBefore, m_forcedNow);
}

}  // namespace stroma
