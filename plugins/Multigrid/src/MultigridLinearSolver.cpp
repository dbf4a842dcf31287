// SPDX-License-Identifier: MIT
#include "MultigridLinearSolver.h"

#include <cmath>
#include <cstdio>

#include "GridTransfer.h"
#include "SparseGrid.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/MechanicalState.h"
#include "simulation/Timing.h"

namespace stroma {

namespace {

/// The first Topology in `node` or below it (depth first).
Topology* findBelow(const Node& node) {
  if (Topology* t = node.get<Topology>()) return t;
  for (const auto& child : node.children())
    if (Topology* t = findBelow(*child)) return t;
  return nullptr;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

void MultigridLinearSolver::init() {
  if (d_fineUpdateInterval.value() != 1 && !d_conjugateGradient.value())
    msgWarning("fineUpdateInterval = " + std::to_string(d_fineUpdateInterval.value()) +
                   " needs conjugateGradient=\"true\" (stationary cycles take their residuals "
                   "from the assembled matrix): the system is assembled at every solve",
               "fineUpdateInterval");
  for (const Data<std::vector<int>>* perLevel : {&d_levelSmoothing, &d_levelCycles})
    for (int count : perLevel->value())
      if (count < 0) {
        msgError("negative count " + std::to_string(count) + " in " + perLevel->name(),
                 perLevel->name());
        break;
      }
  if (!findTopology(nullptr))
    msgError("no grid found: no topology in " +
                 (node() ? node()->path() : std::string("the node")) +
                 ", above it or below it; give topology=\"@path\" to a SparseGridTopology, a "
                 "RegularGridTopology or a hexahedral lattice",
             "topology");
}

Topology* MultigridLinearSolver::findTopology(MechanicalOperations* mop) const {
  if (Topology* t = l_topology.get()) return t;
  if (mop && !mop->independentStates().empty())
    if (const Node* stateNode = mop->independentStates().front()->node())
      if (Topology* t = stateNode->getUp<Topology>()) return t;
  if (!node()) return nullptr;
  if (Topology* t = node()->getUp<Topology>()) return t;
  return findBelow(*node());
}

bool MultigridLinearSolver::prepareGrids(MechanicalOperations& mop) {
  const Topology* topology = findTopology(&mop);
  if (!topology) {
    msgError("no grid found for the solved state: give topology=\"@path\"", "topology");
    return false;
  }
  if (m_gridsReady && topology == m_topology && topology->revision() == m_topologyRevision)
    return true;
  m_gridsReady = false;
  m_topology = topology;
  m_topologyRevision = topology->revision();

  // Level 0: the topology's hexahedra on their lattice.
  sparsegrid::SparseGrid fine;
  std::string error;
  const sparsegrid::SparseGrid* own = topology->sparseGrid();
  if (!multigrid::makeLatticeGrid(topology->positions(), topology->hexahedra(),
                                  own ? &own->box : nullptr, fine, error)) {
    msgError("cannot build the grid from " + topology->path() + ": " + error, "topology");
    return false;
  }
  // Coarser levels and the prolongations between them.
  m_pointP.clear();
  std::vector<std::array<Index, 8>> children;
  for (int l = 0; l < d_levels.value() && fine.cells.size() > 1; ++l) {
    sparsegrid::SparseGrid coarse = sparsegrid::coarsenSparseGrid(fine, &children);
    m_pointP.push_back(multigrid::makeProlongation(fine, coarse, children));
    fine = std::move(coarse);
  }
  d_levelCount.setValue(int(m_pointP.size()) + 1);
  m_fixed.clear();  // the expanded P are made with the fixed set, in solve()
  m_gridsReady = true;
  return true;
}

LinearSolveReport MultigridLinearSolver::fail(MechanicalOperations& mop, VecId x) {
  mop.vOp(x, VecId::null(), VecId::null(), 0.0);
  LinearSolveReport r;
  r.converged = false;
  r.residual = 1;
  return r;
}

LinearSolveReport MultigridLinearSolver::solve(MechanicalOperations& mop,
                                               const MechanicalParams& mp, VecId x, VecId rhs) {
  if (!prepareGrids(mop)) return fail(mop, x);
  // The state must be the grid's points, 3 numbers each.
  const auto& states = mop.independentStates();
  const std::size_t points = m_topology->nbPoints();
  if (states.size() != 1 || states.front()->derivDimension() != 3 ||
      mop.systemSize() != 3 * points) {
    if (!m_reportedBadInput) {
      m_reportedBadInput = true;
      msgError("the solved system has " + std::to_string(mop.systemSize()) + " rows in " +
                   std::to_string(states.size()) + " state(s), but the grid of " +
                   m_topology->path() + " has " + std::to_string(points) +
                   " points: multigrid needs one Vec3 state with one point per grid point",
               "topology");
    }
    return fail(mop, x);
  }

  // Prolongations in the space the constraints allow, remade when the fixed set changes.
  std::vector<char> fixed;
  mop.fixedGlobalRows(fixed);
  const bool patternChanged = fixed != m_fixed || m_P.size() != m_pointP.size();
  // The fine matrix is assembled every fineUpdateInterval solves; in between the cycles keep
  // the operators of the last assembly and the outer CG multiplies through the force fields.
  const int fineInterval = d_conjugateGradient.value() ? d_fineUpdateInterval.value() : 1;
  const bool assembleNow = patternChanged || fineInterval == 1 || m_solvesSinceAssembly == 0 ||
                           (fineInterval > 0 && m_solvesSinceAssembly >= fineInterval);
  if (assembleNow) mop.assemble(mp, m_matrix);
  m_solvesSinceAssembly = assembleNow ? 1 : m_solvesSinceAssembly + 1;
  ScopedPhase phase(mop.timing(), "linearSolve");
  if (patternChanged) {
    m_fixed = std::move(fixed);
    m_P.clear();
    for (std::size_t l = 0; l < m_pointP.size(); ++l)
      m_P.push_back(
          multigrid::expandProlongation(m_pointP[l], 3, l == 0 ? m_fixed : std::vector<char>{}));
  }
  const Eigen::SparseMatrix<double>& A = m_matrix.matrix();
  if (assembleNow) {
    ScopedPhase setup(mop.timing(), "multigridSetup");
    const int interval = d_coarseUpdateInterval.value();
    const bool update = patternChanged || m_assembliesSinceUpdate == 0 ||
                        (interval > 0 && m_assembliesSinceUpdate >= interval);
    multigrid::OperatorUpdate operators;
    operators.patternChanged = patternChanged;
    operators.updateCoarse = update;
    operators.fineSamePattern = m_matrix.patternRevision() == m_fineRevision;
    operators.precision = d_matrixPrecision.value();
    m_cycle.setOperators(A, m_P, operators);
    m_fineRevision = m_matrix.patternRevision();
    m_assembliesSinceUpdate = update ? 1 : m_assembliesSinceUpdate + 1;
  }

  mop.gather(rhs, m_rhs);
  LinearSolveReport report;
  const double normB = m_rhs.norm();
  const bool warm = d_warmStart.value() && m_solution.size() == m_rhs.size() &&
                    m_solution.allFinite() && !patternChanged;
  if (!warm) m_solution.setZero(m_rhs.size());
  if (normB == 0) {
    m_solution.setZero(m_rhs.size());
    mop.scatter(m_solution, x);
    this->report(report);
    return report;
  }
  multigrid::CycleSettings settings;
  settings.smoothingIterations = d_smoothingIterations.value();
  settings.coarseIterations = d_coarseIterations.value();
  settings.directCoarseSolve = d_directCoarseSolve.value();
  settings.postSmoothing = d_postSmoothing.value();
  settings.levelSmoothing = d_levelSmoothing.value();
  settings.levelCycles = d_levelCycles.value();
  report.converged = false;
  if (d_conjugateGradient.value() && fineInterval != 1) {
    const VecId in = mop.allocDeriv(), out = mop.allocDeriv();
    iterateConjugateGradient(productThroughForceFields(mop, mp, in, out), settings, report);
    mop.freeVec(out);
    mop.freeVec(in);
  } else if (d_conjugateGradient.value()) {
    iterateConjugateGradient(
        [&A](const Eigen::VectorXd& in, Eigen::VectorXd& out) { out.noalias() = A * in; },
        settings, report);
  } else {
    iterateCycles(A, normB, warm, settings, report);
  }
  mop.scatter(m_solution, x);
  this->report(report);
  return report;
}

void MultigridLinearSolver::iterateCycles(const Eigen::SparseMatrix<double>& A, double normB,
                                          bool warm, const multigrid::CycleSettings& settings,
                                          LinearSolveReport& report) {
  while (report.iterations < d_iterations.value()) {
    // Full and cascadic cycles start from zero: after a warm start, and after the first cycle,
    // V-cycles improve the current solution instead.
    if (report.iterations == 0 && !warm)
      m_cycle.cycleFromZero(d_cycle.value(), m_rhs, m_solution, settings);
    else
      m_cycle.vCycle(0, m_solution, m_rhs, settings);
    ++report.iterations;
    m_residual.noalias() = m_rhs - A * m_solution;
    report.residual = m_residual.norm() / normB;
    if (!std::isfinite(report.residual)) return;
    if (report.residual <= d_tolerance.value()) {
      report.converged = true;
      return;
    }
  }
}

multigrid::LinearOperator MultigridLinearSolver::productThroughForceFields(
    MechanicalOperations& mop, const MechanicalParams& mp, VecId inVec, VecId outVec) {
  // The assembled system's rows: projected (m M + b B + k K) dx, identity at fixed rows.
  return [this, &mop, mp, inVec, outVec](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    mop.scatter(in, inVec);
    mop.computeMBKdx(mp, outVec, inVec);
    mop.projectResponse(outVec);
    mop.gather(outVec, out);
    for (std::size_t r = 0; r < m_fixed.size(); ++r)
      if (m_fixed[r]) out[Eigen::Index(r)] = in[Eigen::Index(r)];
  };
}

void MultigridLinearSolver::iterateConjugateGradient(const multigrid::LinearOperator& A,
                                                     const multigrid::CycleSettings& settings,
                                                     LinearSolveReport& report) {
  report.iterations = m_cycle.flexibleConjugateGradient(
      A, m_rhs, m_solution, d_iterations.value(), d_tolerance.value(), d_cycle.value(), settings,
      report.residual);
  report.converged = report.residual <= d_tolerance.value();
}

void MultigridLinearSolver::report(const LinearSolveReport& r) {
  ++m_solves;
  d_lastIterations.setValue(r.iterations);
  d_lastResidual.setValue(r.residual);
  if (d_verbose.value())
    msgInfo("multigrid: " + std::to_string(r.iterations) + " cycles, relative residual " +
            number(r.residual));
  if (r.converged) return;
  if (m_unconverged++ == 0)
    msgWarning("multigrid stopped after " + std::to_string(r.iterations) +
                   " cycles without converging: relative residual " + number(r.residual) +
                   " > tolerance " + number(d_tolerance.value()) +
                   " (raise iterations, levels or smoothingIterations); later ones are counted",
               "iterations");
}

void MultigridLinearSolver::cleanup() {
  if (m_unconverged > 1)
    msgWarning("multigrid did not converge in " + std::to_string(m_unconverged) + " of " +
                   std::to_string(m_solves) + " solves",
               "iterations");
}

}  // namespace stroma
