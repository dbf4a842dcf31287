// SPDX-License-Identifier: MIT
// Multigrid cycles on nested levels with conjugate gradient as the smoother (Nesme 2008, seed
// 001, ch. 5 sec. 3; Briggs, Henson and McCormick 2000, "A Multigrid Tutorial", ch. 3).
//
// Operators: A_0 is the system matrix; A_{l+1} = P_l^T A_l P_l (Galerkin), so that each coarse
// level solves the fine problem restricted to the coarse interpolated fields.
//
// V-cycle on level l for A_l x = b (x is the start and the result):
//   1. pre-smoothing: `smoothingIterations` CG iterations from x;
//   2. restriction of the residual: r_{l+1} = P_l^T (b - A_l x), the residual the smoother's CG
//      left (no further product);
//   3. coarse correction: e = V-cycle on level l + 1 for A_{l+1} e = r_{l+1}, from e = 0; on the
//      coarsest level, CG for `coarseIterations` (stopping at a relative residual of 1e-12) or a
//      direct LDL^T solve;
//   4. x += P_l e, then (postSmoothing) `smoothingIterations` CG iterations from x.
// Full cycle: b is restricted to every level, the coarsest solved, and each finer level starts
// a V-cycle from the prolongation of the coarser level's result (Briggs et al. ch. 3, "full
// multigrid V-cycle").
//
// CG on a level whose P has zeroed rows (fixed degrees of freedom) meets coarse unknowns that
// interpolate only fixed points: their rows of A_{l+1} are zero, and so are their residuals,
// so CG never moves them; the direct solve puts 1 on those diagonals.
#pragma once

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <vector>

namespace stroma::multigrid {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct CycleSettings {
  int smoothingIterations = 7;
  int coarseIterations = 150;
  bool directCoarseSolve = false;
  bool postSmoothing = true;
};

class MultigridCycle {
 public:
  /// Keeps `A0` by reference (it must outlive the cycles) and computes the Galerkin operators
  /// A_{l+1} = P_l^T A_l P_l for the prolongations `P` (P[l]: level l + 1 to level l). Set
  /// `patternChanged` when P changed since the last call (the direct coarse solver then redoes
  /// its symbolic analysis). Without `updateCoarse` (and with an unchanged pattern), the coarse
  /// operators of the last update are kept: only A0 is new.
  void setOperators(const SparseMatrix& A0, const std::vector<SparseMatrix>& P, bool patternChanged,
                    bool updateCoarse = true);

  /// Number of levels, fine one included.
  int levels() const { return int(m_P.size()) + 1; }
  const SparseMatrix& matrix(int level) const { return level == 0 ? *m_A0 : m_coarse[level - 1]; }

  /// One V-cycle on level `level` (0 = finest) from and into x.
  void vCycle(int level, Eigen::VectorXd& x, const Eigen::VectorXd& b,
              const CycleSettings& settings);
  /// One full multigrid cycle on level 0 (x is overwritten).
  void fullCycle(Eigen::VectorXd& x, const Eigen::VectorXd& b, const CycleSettings& settings);

  /// Flexible CG on A x = b from x (Notay 2000, "Flexible conjugate gradients", SIAM J. Sci.
  /// Comput. 22: the Polak-Ribiere beta, since a cycle with CG smoothers is not a fixed linear
  /// operator), each iteration preconditioned by one cycle from zero (`full`: a full cycle,
  /// else a V-cycle) and one product with A (A may differ from the level-0 operator of the
  /// cycles, e.g. when they are stale). Stops after `iterations` or at a relative residual
  /// ||b - A x|| / ||b|| <= tolerance. Returns the iterations; `residual` is the relative
  /// residual of the x returned.
  int flexibleConjugateGradient(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                int iterations, double tolerance, bool full,
                                const CycleSettings& settings, double& residual);

  /// `iterations` CG iterations on A x = b from x; stops earlier when ||r|| <= tolerance ||b||
  /// or when p.Ap is not positive (a converged or singular direction). Returns the iterations
  /// and leaves in r the residual b - A x (updated recursively, as CG does).
  static int conjugateGradient(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                               int iterations, double tolerance, Eigen::VectorXd& r,
                               Eigen::VectorXd& p, Eigen::VectorXd& q);

 private:
  void solveCoarsest(Eigen::VectorXd& x, const Eigen::VectorXd& b, const CycleSettings& settings);

  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z, bool full,
                    const CycleSettings& settings);

  struct Work {
    Eigen::VectorXd r, p, q, residual, coarseRhs, coarseX;
  };
  const SparseMatrix* m_A0 = nullptr;
  std::vector<const SparseMatrix*> m_P;
  std::vector<SparseMatrix> m_PT;      ///< P_l^T, remade when the pattern changes
  SparseMatrix m_AP;                   ///< scratch: A_l P_l
  std::vector<SparseMatrix> m_coarse;  ///< A_1 ... A_L
  std::vector<Work> m_work;            ///< per level
  std::vector<Eigen::VectorXd> m_fullRhs;
  Eigen::VectorXd m_r, m_z, m_d, m_q, m_previousR;  ///< flexible CG
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> m_direct;
  bool m_directAnalyzed = false;
  bool m_directFactorized = false;  ///< m_direct holds the factors of the current A_L
  SparseMatrix m_coarsestRegular;   ///< A_L with 1 on zero diagonals, for the direct solve
};

}  // namespace stroma::multigrid
