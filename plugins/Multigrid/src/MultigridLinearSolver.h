// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "MultigridCycle.h"
#include "core/DataTraits.h"
#include "core/Link.h"
#include "linalg/AssembledMatrix.h"
#include "simulation/Solvers.h"
#include "topology/SparseGridLevels.h"
#include "topology/Topology.h"

namespace stroma {

using MultigridCycleKind = multigrid::CycleKind;

template <>
struct EnumKeywords<multigrid::CycleKind> {
  static constexpr std::array<std::string_view, 3> names{"V", "full", "cascadic"};
};

template <>
struct EnumKeywords<multigrid::SymmetricBlockMatrix::Precision> {
  static constexpr std::array<std::string_view, 2> names{"double", "single"};
};

/// Geometric multigrid on nested hexahedral grids (Nesme 2008, seed 001, ch. 5 sec. 3), for
/// (m M + b B + k K) x = rhs like any LinearSolver: EulerImplicitSolver, StaticSolver and
/// NewtonRaphsonSolver use it unchanged.
///
/// Grid: the hexahedra of the `topology` link, else of the first Topology at or above the node
/// of the solved state (else of the solver's node). Supported: SparseGridTopology (its box),
/// RegularGridTopology and any hexahedral topology whose hexahedra are cells of one
/// axis-aligned regular lattice. The state must be one Vec3 state with a point per topology
/// point. Level 0 is those hexahedra; `levels` coarser levels come from 2 x 2 x 2 grouping
/// (fewer when a level is down to one cell). Prolongation = trilinear interpolation
/// (GridTransfer.h), restriction = its transpose, coarse operators A_{l+1} = P^T A_l P
/// (Galerkin; for a linear material on full cells they equal the stiffness of the coarse grid,
/// seed 001 ch. 4 sec. 3), smoother = CG (MultigridCycle.h).
///
/// Constraints: A_0 is assembled with the fixed rows as identity (as SparseLDLSolver); the rows
/// of P at fixed degrees of freedom (MechanicalOperations::fixedGlobalRows) are zeroed, so coarse
/// corrections never move a fixed point and the identity rows do not enter A_1.
///
/// Each solve assembles A_0; the Galerkin operators (whose values change for a corotational
/// model) are recomputed every `coarseUpdateInterval` solves; the grids and P are rebuilt only
/// when the topology or the set of fixed degrees of freedom changed. With `conjugateGradient`,
/// the cycles precondition an outer flexible CG (MultigridCycle::flexibleConjugateGradient),
/// which keeps the convergence when coarse hexahedra lock (bending, nu near 0.5) and when the
/// coarse operators are stale.
/// Reports iterations (cycles) and the relative residual like
/// CGLinearSolver, warning once when `tolerance` is not reached.
class MultigridLinearSolver final : public LinearSolver {
 public:
  Data<int> d_levels{this,
                     "levels",
                     4,
                     "Coarse levels below the simulated grid (0: plain CG with "
                     "coarseIterations on the fine level).",
                     {.min = 0.0, .max = 30.0}};
  Data<MultigridCycleKind> d_cycle{
      this, "cycle", MultigridCycleKind::V,
      "V (V-cycle from the fine level), full (full multigrid: the coarsest level solved, then a "
      "V-cycle on each finer level from the prolongation of the coarser result) or cascadic (the "
      "same nesting with levelSmoothing CG iterations on each finer level instead of a V-cycle, "
      "Bornemann and Deuflhard 1996: cheap when the coarse levels are accurate)."};
  Data<int> d_iterations{
      this, "iterations", 1, "Maximum number of cycles per solve.", {.min = 1.0}};
  Data<double> d_tolerance{this,
                           "tolerance",
                           1e-5,
                           "Relative residual ||rhs - A x|| / ||rhs|| at which to stop cycling "
                           "(0: always do `iterations` cycles).",
                           {.min = 0.0}};
  Data<int> d_smoothingIterations{this,
                                  "smoothingIterations",
                                  7,
                                  "CG iterations of each smoothing on every level but the "
                                  "coarsest (seed 001 table 5.2: 7).",
                                  {.min = 0.0}};
  Data<std::vector<int>> d_levelSmoothing{
      this, "levelSmoothing", {},
      "Smoothing (cascadic: CG) iterations per level, finest first, the last repeated on coarser "
      "levels; empty: smoothingIterations everywhere. A coarse level costs 1/8 of the next finer "
      "one: e.g. \"1 8\" smooths little on the fine level and much on the coarse ones."};
  Data<std::vector<int>> d_levelCycles{
      this, "levelCycles", {},
      "cycle=\"full\": V-cycles on each level after the prolongation of the coarser result, "
      "finest first, the last repeated; empty: 1 everywhere (classical full multigrid). A 0 "
      "on the finest level returns the prolongation of the next level's result: enough when "
      "the coarse discretization is as accurate as the solve needs to be."};
  Data<multigrid::SymmetricBlockMatrix::Precision> d_matrixPrecision{
      this, "matrixPrecision", multigrid::SymmetricBlockMatrix::Precision::double_,
      "Storage of the level matrices the cycles multiply with, as 3 x 3 blocks: double or "
      "single. The smoothing products are memory bound, and single reads about half the bytes; "
      "the outer flexible CG (conjugateGradient) and the residuals of stationary cycles use "
      "the assembled matrix in double, so single precision limits only stationary cycles (to a "
      "relative residual near 1e-7)."};
  Data<bool> d_postSmoothing{this, "postSmoothing", true,
                             "Smooth again after the coarse correction."};
  Data<int> d_coarseIterations{this,
                               "coarseIterations",
                               150,
                               "CG iterations on the coarsest level (seed 001 table 5.2: 150).",
                               {.min = 1.0}};
  Data<bool> d_directCoarseSolve{this, "directCoarseSolve", false,
                                 "Solve the coarsest level with LDL^T instead of CG."};
  Data<bool> d_conjugateGradient{this, "conjugateGradient", false,
                                 "Use each cycle (from zero) as the preconditioner of an outer "
                                 "flexible conjugate gradient: an iteration is then one cycle and "
                                 "one product with A."};
  Data<int> d_coarseUpdateInterval{
      this,
      "coarseUpdateInterval",
      1,
      "Recompute the Galerkin coarse operators every this many solves (1: every solve; 0: only "
      "when the grid or the fixed set changes). Between updates the coarse levels keep the "
      "operators of an earlier matrix: for a corotational model a slightly stale "
      "preconditioner, which the outer conjugateGradient absorbs; the fine level always uses "
      "the current matrix.",
      {.min = 0.0}};
  Data<int> d_fineUpdateInterval{
      this,
      "fineUpdateInterval",
      1,
      "With conjugateGradient: assemble the system every this many solves (1: every solve; 0: "
      "only when the fixed set changes). In between, the cycles keep the matrices of the last "
      "assembly (a stale preconditioner, like coarseUpdateInterval, which counts assemblies) and "
      "the outer CG multiplies through the force fields and masses (computeMBKdx), so the "
      "solution is that of the current system; the assembly (the largest cost of a step on a "
      "fine grid) is then paid once per interval.",
      {.min = 0.0}};
  Data<bool> d_warmStart{this, "warmStart", false,
                         "Start each solve from the previous solve's solution instead of zero "
                         "(an implicit step's velocity change varies slowly from step to "
                         "step)."};
  Link<Topology> l_topology{this, "topology",
                            "Topology whose hexahedra are the fine grid (default: the one at or "
                            "above the solved state's node)."};
  Data<bool> d_verbose{this, "verbose", false, "Report every solve."};
  Data<int> d_levelCount{
      this, "levelCount", 0, "Levels built, the fine one included.", {.output = true}};
  Data<int> d_lastIterations{
      this, "lastIterations", 0, "Cycles of the last solve.", {.output = true}};
  Data<double> d_lastResidual{
      this, "lastResidual", 0.0, "Relative residual of the last solve.", {.output = true}};

  void init() override;
  LinearSolveReport solve(MechanicalOperations& mop, const MechanicalParams& mp, VecId x,
                          VecId rhs) override;
  void cleanup() override;

 private:
  Topology* findTopology(MechanicalOperations* mop) const;
  /// Builds the grids and P when the topology changed; false (with an error) on bad input.
  bool prepareGrids(MechanicalOperations& mop);
  LinearSolveReport fail(MechanicalOperations& mop, VecId x);
  /// Stationary cycles (x += cycle correction) or flexible CG preconditioned by a cycle.
  void iterateCycles(const Eigen::SparseMatrix<double>& A, double normB, bool warm,
                     const multigrid::CycleSettings& settings, LinearSolveReport& report);
  /// The product with the system through the force fields and masses (computeMBKdx), as the
  /// assembled matrix would give it, with the state vectors `in` and `out` as scratch: for the
  /// solves that do not assemble.
  multigrid::LinearOperator productThroughForceFields(MechanicalOperations& mop,
                                                      const MechanicalParams& mp, VecId in,
                                                      VecId out);
  void iterateConjugateGradient(const multigrid::LinearOperator& A,
                                const multigrid::CycleSettings& settings,
                                LinearSolveReport& report);
  void report(const LinearSolveReport& r);

  AssembledMatrix m_matrix;
  multigrid::MultigridCycle m_cycle;
  std::vector<Eigen::SparseMatrix<double, Eigen::RowMajor>> m_pointP;  ///< per level, scalar
  std::vector<multigrid::SparseMatrix> m_P;                            ///< per level, expanded
  std::vector<char> m_fixed;
  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = 0;
  bool m_gridsReady = false;
  bool m_reportedBadInput = false;
  Eigen::VectorXd m_rhs, m_solution, m_residual;
  long long m_unconverged = 0, m_solves = 0;
  int m_assembliesSinceUpdate = 0;  ///< assemblies since the coarse operators were computed
  int m_solvesSinceAssembly = 0;    ///< solves since the fine matrix was assembled
  std::uint64_t m_fineRevision = ~std::uint64_t{0};  ///< m_matrix's pattern at the last setup
};

}  // namespace stroma
