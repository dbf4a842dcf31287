// SPDX-License-Identifier: MIT
#include "simulation/MechanicalOperations.h"

#include <algorithm>
#include <cmath>

#include "core/Message.h"
#include "core/Node.h"
#include "simulation/ForceField.h"
#include "simulation/Mapping.h"
#include "simulation/Mass.h"
#include "simulation/ProjectiveConstraint.h"
#include "simulation/Solvers.h"
#include "simulation/Timing.h"

namespace stroma {

MechanicalOperations::MechanicalOperations(Node& solverNode, Timing& timing, double dt)
    : m_node(&solverNode), m_timing(&timing), m_dt(dt) {
  collectAll();
}

void MechanicalOperations::reset(Node& solverNode, Timing& timing, double dt) {
  m_dt = dt;
  m_timing = &timing;
  std::size_t at = 0;
  const bool unchanged = m_node == &solverNode && fingerprint(solverNode, true, at, true) &&
                         at == m_fingerprint.size();
  // Released on the states only while they are known to be alive (the graph unchanged).
  freeTemporaries(unchanged);
  if (unchanged) return;
  m_node = &solverNode;
  collectAll();
}

void MechanicalOperations::collectAll() {
  m_states.clear();
  m_independent.clear();
  m_foreign.clear();
  m_forceFields.clear();
  m_masses.clear();
  m_constraints.clear();
  m_mappings.clear();
  m_loadedMappings.clear();
  m_offsets.clear();
  m_systemSize = 0;
  collect(*m_node, true);
  collectInteractions();
  for (BaseMechanicalState* s : m_states) {
    const bool mapped = std::any_of(m_mappings.begin(), m_mappings.end(),
                                    [&](const BaseMapping* m) { return m->toState() == s; });
    if (mapped) continue;
    m_independent.push_back(s);
    m_offsets.push_back(m_systemSize);
    m_systemSize += s->matrixSize();
  }
  collectLoadedMappings();
  m_stateOffsets = std::make_unique<StateOffsets>();
  for (std::size_t i = 0; i < m_independent.size(); ++i)
    m_stateOffsets->set(m_independent[i], m_offsets[i]);
  std::size_t at = 0;
  fingerprint(*m_node, true, at, false);
  m_fingerprint.resize(at);
}

// What collect and collectInteractions read, as a sequence of words: each object's address and
// validity, a state's size, a mapping's two ends, per node its activation and where its
// objects end; then the ancestors' objects (interaction force fields, contact responses). The
// same walk as collect, without allocating.
bool MechanicalOperations::fingerprint(Node& node, bool isSolverNode, std::size_t& at,
                                       bool compare) {
  auto put = [&](std::uintptr_t word) {
    if (compare) return at < m_fingerprint.size() && m_fingerprint[at++] == word;
    if (at == m_fingerprint.size()) m_fingerprint.push_back(word);
    else m_fingerprint[at] = word;
    ++at;
    return true;
  };
  auto putObjects = [&](const Node& n) {
    for (const auto& object : n.objects()) {
      const Base* o = object.get();
      if (!put(reinterpret_cast<std::uintptr_t>(o)) || !put(o->isValid())) return false;
      if (auto* s = dynamic_cast<const BaseMechanicalState*>(o); s && !put(s->matrixSize()))
        return false;
      if (auto* m = dynamic_cast<const BaseMapping*>(o))
        if (!put(reinterpret_cast<std::uintptr_t>(m->toState())) ||
            !put(reinterpret_cast<std::uintptr_t>(m->fromState())))
          return false;
    }
    return put(0);
  };
  if (!put(reinterpret_cast<std::uintptr_t>(&node)) || !put(node.d_activated.value())) return false;
  if (!node.d_activated.value()) return true;
  if (!isSolverNode && node.get<OdeSolver>()) return true;
  if (!putObjects(node)) return false;
  for (const auto& child : node.children())
    if (!fingerprint(*child, false, at, compare)) return false;
  if (!put(0)) return false;
  if (isSolverNode)
    for (Node* n = node.parent(); n; n = n->parent())
      if (!putObjects(*n)) return false;
  return true;
}

// A mapping matters to forces and increments only when its output, or a state mapped further
// from it, carries a force field or a mass. A surface mapped only to be drawn or collided
// carries neither: pushing dx through it and zeros back at every CG iteration is wasted work
// (it was 76 % of a step of a grid with a 21,000-point surface). Positions and velocities still
// follow every mapping in propagate().
void MechanicalOperations::collectLoadedMappings() {
  std::vector<const BaseMechanicalState*>& loaded = m_loadedScratch;
  loaded.clear();
  for (const BaseForceField* ff : m_forceFields)
    for (const BaseMechanicalState* s : ff->states()) loaded.push_back(s);
  std::vector<char>& needed = m_neededScratch;
  needed.assign(m_mappings.size(), 0);
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 0; i < m_mappings.size(); ++i) {
      if (needed[i] ||
          std::find(loaded.begin(), loaded.end(), m_mappings[i]->toState()) == loaded.end())
        continue;
      needed[i] = 1;
      loaded.push_back(m_mappings[i]->fromState());
      grew = true;
    }
  }
  for (std::size_t i = 0; i < m_mappings.size(); ++i)
    if (needed[i]) m_loadedMappings.push_back(m_mappings[i]);
}

// A solver's operations end with the scene, after some of its states may be gone: they are
// not touched then (vFree only lets a state reuse the vector's storage).
MechanicalOperations::~MechanicalOperations() { freeTemporaries(false); }

void MechanicalOperations::freeTemporaries(bool onStates) {
  if (onStates)
    for (VecId v : m_temporaries) {
      for (BaseMechanicalState* s : m_states) s->vFree(v);
      for (BaseMechanicalState* s : m_foreign) s->vFree(v);
    }
  m_temporaries.clear();
  m_nextCoord = VecId::kFirstTemporary;
  m_nextDeriv = VecId::kFirstTemporary;
}

void MechanicalOperations::collectInteractions() {
  auto isOurs = [&](const BaseMechanicalState* s) {
    return std::find(m_states.begin(), m_states.end(), s) != m_states.end();
  };
  // Force fields of the ancestors that act on one of this solver's states.
  for (Node* n = m_node->parent(); n; n = n->parent())
    for (const auto& object : n->objects()) {
      auto* ff = dynamic_cast<BaseForceField*>(object.get());
      if (!ff || !ff->isValid()) continue;
      const auto states = ff->states();
      if (std::any_of(states.begin(), states.end(), isOurs)) m_forceFields.push_back(ff);
    }
  for (const BaseForceField* ff : m_forceFields)
    for (BaseMechanicalState* s : ff->states())
      if (s && !isOurs(s) && std::find(m_foreign.begin(), m_foreign.end(), s) == m_foreign.end())
        m_foreign.push_back(s);
}

// The subtree of the solver node, minus sub-nodes that have their own ODE solver.
void MechanicalOperations::collect(Node& node, bool isSolverNode) {
  if (!node.d_activated.value()) return;
  if (!isSolverNode && node.get<OdeSolver>()) return;
  for (const auto& object : node.objects()) {
    Base* o = object.get();
    if (!o->isValid()) continue;
    if (auto* s = dynamic_cast<BaseMechanicalState*>(o)) m_states.push_back(s);
    if (auto* f = dynamic_cast<BaseForceField*>(o)) m_forceFields.push_back(f);
    if (auto* m = dynamic_cast<BaseMass*>(o)) m_masses.push_back(m);
    if (auto* c = dynamic_cast<BaseProjectiveConstraint*>(o)) m_constraints.push_back(c);
    if (auto* m = dynamic_cast<BaseMapping*>(o); m && m->toState() && m->fromState())
      m_mappings.push_back(m);
  }
  for (const auto& child : node.children()) collect(*child, false);
}

double MechanicalOperations::time() const { return m_node->time(); }

VecId MechanicalOperations::allocDeriv() {
  const VecId v = VecId::deriv(m_nextDeriv++);
  for (BaseMechanicalState* s : m_states) s->vAlloc(v);
  for (BaseMechanicalState* s : m_foreign) s->vAlloc(v);
  m_temporaries.push_back(v);
  return v;
}

VecId MechanicalOperations::allocCoord() {
  const VecId v = VecId::coord(m_nextCoord++);
  for (BaseMechanicalState* s : m_states) s->vAlloc(v);
  for (BaseMechanicalState* s : m_foreign) s->vAlloc(v);
  m_temporaries.push_back(v);
  return v;
}

void MechanicalOperations::freeVec(VecId v) {
  for (BaseMechanicalState* s : m_states) s->vFree(v);
  for (BaseMechanicalState* s : m_foreign) s->vFree(v);
  m_temporaries.erase(std::remove(m_temporaries.begin(), m_temporaries.end(), v),
                      m_temporaries.end());
}

void MechanicalOperations::vOp(VecId v, VecId a, VecId b, double f) {
  for (BaseMechanicalState* s : m_independent) s->vOp(v, a, b, f);
}

double MechanicalOperations::dot(VecId a, VecId b) const {
  double sum = 0;
  for (const BaseMechanicalState* s : m_independent) sum += s->vDot(a, b);
  return sum;
}

double MechanicalOperations::norm(VecId a) const { return std::sqrt(dot(a, a)); }

void MechanicalOperations::clearOnAll(VecId v) {
  for (BaseMechanicalState* s : m_states) s->vOp(v, VecId::null(), VecId::null(), 0.0);
}

void MechanicalOperations::computeForce(const MechanicalParams& mp, VecId f) {
  ScopedPhase phase(*m_timing, "computeForce");
  clearOnAll(f);
  for (BaseForceField* ff : m_forceFields) ff->accumulateForce(mp, f);
  for (auto it = m_loadedMappings.rbegin(); it != m_loadedMappings.rend(); ++it)
    (*it)->applyTransposed(f, f);
}

void MechanicalOperations::propagateDx(VecId dx) {
  for (BaseMapping* m : m_loadedMappings) m->applyVelocities(dx, dx);
}

void MechanicalOperations::computeMBKdx(const MechanicalParams& mp, VecId out, VecId dx) {
  ScopedPhase phase(*m_timing, "computeMBKdx");
  propagateDx(dx);
  clearOnAll(out);
  if (mp.kFactor != 0 || mp.bFactor != 0)
    for (BaseForceField* ff : m_forceFields) ff->accumulateDForce(mp, out, dx);
  if (mp.mFactor != 0)
    for (BaseMass* m : m_masses) m->accumulateMDx(out, dx, mp.mFactor);
  for (auto it = m_loadedMappings.rbegin(); it != m_loadedMappings.rend(); ++it)
    (*it)->applyTransposed(out, out);
}

bool MechanicalOperations::accFromF(VecId a, VecId f) {
  for (BaseMechanicalState* s : m_independent) {
    BaseMass* mass = nullptr;
    for (BaseMass* m : m_masses) {
      const auto states = m->states();
      if (std::find(states.begin(), states.end(), s) != states.end()) mass = m;
    }
    if (!mass || !mass->isDiagonal()) {
      s->msgError(mass ? "explicit integration needs a lumped (diagonal) mass; " +
                             mass->className() + " is not one"
                       : "has no mass: add UniformMass, DiagonalMass or MeshMatrixMass");
      return false;
    }
    mass->accumulateAccFromF(a, f);
  }
  return true;
}

void MechanicalOperations::projectResponse(VecId dx) {
  for (BaseProjectiveConstraint* c : m_constraints) c->constrainResponse(dx);
}

void MechanicalOperations::projectPosition(VecId x) {
  for (BaseProjectiveConstraint* c : m_constraints) c->constrainPosition(x, endTime());
}

void MechanicalOperations::projectVelocity(VecId v) {
  for (BaseProjectiveConstraint* c : m_constraints) c->constrainVelocity(v, endTime());
}

void MechanicalOperations::propagate(VecId x, VecId v) {
  ScopedPhase phase(*m_timing, "mappings");
  for (BaseMapping* m : m_mappings) {
    m->applyPositions(x, x);
    m->applyVelocities(v, v);
  }
}

void MechanicalOperations::fixedGlobalRows(std::vector<char>& fixed) const {
  fixed.assign(m_systemSize, 0);
  std::vector<std::size_t>& rows = m_rowsScratch;
  for (const BaseProjectiveConstraint* c : m_constraints) {
    const auto it = std::find(m_independent.begin(), m_independent.end(), c->state());
    if (it == m_independent.end()) continue;
    const std::size_t offset = m_offsets[static_cast<std::size_t>(it - m_independent.begin())];
    rows.clear();
    c->fixedRows(rows);
    for (std::size_t r : rows)
      if (offset + r < m_systemSize) fixed[offset + r] = 1;
  }
}

bool MechanicalOperations::contains(const BaseMechanicalState* state) const {
  return std::find(m_states.begin(), m_states.end(), state) != m_states.end();
}

bool MechanicalOperations::independentOffset(const BaseMechanicalState* state,
                                             std::size_t& offset) const {
  const auto it = std::find(m_independent.begin(), m_independent.end(), state);
  if (it == m_independent.end()) return false;
  offset = m_offsets[static_cast<std::size_t>(it - m_independent.begin())];
  return true;
}

Eigen::SparseMatrix<double> MechanicalOperations::totalJacobian(const BaseMechanicalState* state) {
  const auto n = static_cast<Eigen::Index>(m_systemSize);
  const auto it = std::find(m_independent.begin(), m_independent.end(), state);
  if (it != m_independent.end()) {
    const std::size_t offset = m_offsets[static_cast<std::size_t>(it - m_independent.begin())];
    const auto rows = static_cast<Eigen::Index>(state->matrixSize());
    Eigen::SparseMatrix<double> selection(rows, n);
    std::vector<Eigen::Triplet<double>> ones;
    for (Eigen::Index r = 0; r < rows; ++r)
      ones.emplace_back(r, static_cast<Eigen::Index>(offset) + r, 1.0);
    selection.setFromTriplets(ones.begin(), ones.end());
    return selection;
  }
  for (BaseMapping* m : m_mappings)
    if (m->toState() == state) return m->jacobian() * totalJacobian(m->fromState());
  // A state mapped from outside this solver's system: it contributes nothing here.
  return Eigen::SparseMatrix<double>(static_cast<Eigen::Index>(state->matrixSize()), n);
}

namespace {
// Drops the entries of fixed rows and columns on their way into the matrix.
class ProjectedAccumulator final : public MatrixAccumulator {
 public:
  ProjectedAccumulator(MatrixAccumulator& target, const std::vector<char>& fixed)
      : m_target(target), m_fixed(fixed) {}
  void add(std::size_t row, std::size_t col, double value) override {
    if (!m_fixed[row] && !m_fixed[col]) m_target.add(row, col, value);
  }
  // A block with no fixed row or column goes through whole (one call instead of 9).
  void addBlock(std::size_t row, std::size_t col, const Eigen::Matrix3d& block) override {
    if (m_fixed[row] | m_fixed[row + 1] | m_fixed[row + 2] | m_fixed[col] | m_fixed[col + 1] |
        m_fixed[col + 2])
      MatrixAccumulator::addBlock(row, col, block);
    else
      m_target.addBlock(row, col, block);
  }
  // An element whose nodes are all free goes through in one call (AssembledMatrix adds its
  // blocks in place at once); otherwise block by block, dropping the fixed entries.
  void addBlocks(std::span<const std::size_t> offsets, const Eigen::Ref<const Eigen::MatrixXd>& M,
                 double factor) override {
    for (std::size_t offset : offsets)
      if (m_fixed[offset] | m_fixed[offset + 1] | m_fixed[offset + 2]) {
        MatrixAccumulator::addBlocks(offsets, M, factor);
        return;
      }
    m_target.addBlocks(offsets, M, factor);
  }

 private:
  MatrixAccumulator& m_target;
  const std::vector<char>& m_fixed;
};
}  // namespace

void MechanicalOperations::assemble(const MechanicalParams& mp, AssembledMatrix& A) {
  ScopedPhase phase(*m_timing, "assemble");
  std::vector<char>& fixed = m_fixedScratch;
  fixedGlobalRows(fixed);
  A.begin(m_systemSize);
  ProjectedAccumulator projected(A, fixed);
  const StateOffsets& offsets = *m_stateOffsets;
  for (BaseForceField* ff : m_forceFields)
    if (mp.kFactor != 0 || mp.bFactor != 0) ff->accumulateKMatrix(mp, projected, offsets);
  if (mp.mFactor != 0)
    for (BaseMass* m : m_masses) m->accumulateMMatrix(projected, offsets, mp.mFactor);

  // Mapped states: J^T (local matrix) J.
  for (BaseMechanicalState* s : m_states) {
    if (std::find(m_independent.begin(), m_independent.end(), s) != m_independent.end()) continue;
    AssembledMatrix local;
    local.begin(s->matrixSize());
    StateOffsets localOffsets;
    localOffsets.set(s, 0);
    for (BaseForceField* ff : m_forceFields)
      if (mp.kFactor != 0 || mp.bFactor != 0) ff->accumulateKMatrix(mp, local, localOffsets);
    if (mp.mFactor != 0)
      for (BaseMass* m : m_masses) m->accumulateMMatrix(local, localOffsets, mp.mFactor);
    local.finish();
    if (local.matrix().nonZeros() == 0) continue;
    const Eigen::SparseMatrix<double> J = totalJacobian(s);
    const Eigen::SparseMatrix<double> G = Eigen::SparseMatrix<double>(J.transpose()) *
                                          local.matrix() * J;
    for (Eigen::Index k = 0; k < G.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator e(G, k); e; ++e)
        projected.add(static_cast<std::size_t>(e.row()), static_cast<std::size_t>(e.col()),
                      e.value());
  }
  for (std::size_t r = 0; r < m_systemSize; ++r)
    if (fixed[r]) A.add(r, r, 1.0);
  A.finish();
}

void MechanicalOperations::gather(VecId v, Eigen::VectorXd& out) const {
  out.resize(static_cast<Eigen::Index>(m_systemSize));
  for (std::size_t i = 0; i < m_independent.size(); ++i)
    m_independent[i]->copyToGlobal(v, out, m_offsets[i]);
}

void MechanicalOperations::scatter(const Eigen::VectorXd& in, VecId v) {
  for (std::size_t i = 0; i < m_independent.size(); ++i)
    m_independent[i]->copyFromGlobal(v, in, m_offsets[i]);
}

double MechanicalOperations::potentialEnergy(const MechanicalParams& mp) const {
  double e = 0;
  for (const BaseForceField* ff : m_forceFields) e += ff->energy(mp);
  return e;
}

double MechanicalOperations::kineticEnergy() const {
  double e = 0;
  for (const BaseMass* m : m_masses) e += m->kineticEnergyAt(VecId::velocity());
  return e;
}

bool MechanicalOperations::checkFinite(VecId v, const std::string& what, Base& reporter) const {
  const WorstVertex worst = worstVertex(v);
  if (!worst.state || std::isfinite(worst.value)) return true;
  reporter.msgError("the simulation diverged at time " + std::to_string(endTime()) + ": " + what +
                    " of " + worst.state->path() + " is not finite at index " +
                    std::to_string(worst.index));
  return false;
}

MechanicalOperations::WorstVertex MechanicalOperations::worstVertex(VecId v) const {
  WorstVertex worst;
  for (const BaseMechanicalState* s : m_independent) {
    std::size_t where = 0;
    const double value = s->vMaxAbs(v, where);
    if (worst.state && std::isfinite(value) && value <= worst.value) continue;
    worst = {s, where, value};
    if (!std::isfinite(value)) break;  // the first non-finite value is the one to report
  }
  return worst;
}

std::string MechanicalOperations::describeWorstVertex(VecId v, const std::string& what) const {
  const WorstVertex worst = worstVertex(v);
  if (!worst.state) return "no state";
  return "vertex " + std::to_string(worst.index) + " of " + worst.state->path() + " (|" + what +
         "| component " + formatNumber(worst.value) + ")";
}

OdeSolver::OdeSolver() = default;
OdeSolver::~OdeSolver() = default;

MechanicalOperations& OdeSolver::operations(Node& node, Timing& timing, double dt) {
  if (!m_operations) m_operations = std::make_unique<MechanicalOperations>(node, timing, dt);
  else m_operations->reset(node, timing, dt);
  return *m_operations;
}

}  // namespace stroma
