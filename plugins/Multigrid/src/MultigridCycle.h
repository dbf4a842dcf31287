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
#include <algorithm>
#include <functional>
#include <vector>

#include "SymmetricBlockMatrix.h"

namespace stroma::multigrid {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct CycleSettings {
  int smoothingIterations = 7;
  int coarseIterations = 150;
  bool directCoarseSolve = false;
  bool postSmoothing = true;
  /// Smoothing iterations per level, finest first, overriding smoothingIterations where given
  /// (the last entry repeats on coarser levels): a coarse level costs 1/8 of its finer one, so
  /// smoothing more there and less on the fine level is cheap.
  std::vector<int> levelSmoothing = {};
  /// Full cycle: V-cycles on each level after the prolongation of the coarser result, finest
  /// first, the last entry repeated (empty: 1 everywhere, the classical full multigrid). 0 on
  /// the finest level returns the prolongation of the level below: enough when the coarse
  /// discretization is already as accurate as wanted, at the price of two fine transfers.
  std::vector<int> levelCycles = {};

  int smoothingAt(int level) const { return at(levelSmoothing, level, smoothingIterations); }
  int cyclesAt(int level) const { return at(levelCycles, level, 1); }

 private:
  static int at(const std::vector<int>& perLevel, int level, int otherwise) {
    if (perLevel.empty()) return otherwise;
    return perLevel[std::min<std::size_t>(std::size_t(level), perLevel.size() - 1)];
  }
};

/// The cycle of a multigrid iteration: V (above), full (above), or cascadic (Bornemann and
/// Deuflhard 1996, "The cascadic multigrid method for elliptic problems", Numer. Math. 75): b
/// restricted to every level, the coarsest solved, then on each finer level CG for
/// smoothingAt(level) iterations from the prolongation of the coarser result, with no coarse
/// correction going back. Cascadic is the cheapest way to the discretization error when the
/// coarse levels are accurate: the fine level costs 1 + smoothingAt(0) products (none when it
/// is 0: the interpolated result).
enum class CycleKind { V, full, cascadic };

/// What changed since the last MultigridCycle::setOperators, and how to store the levels.
struct OperatorUpdate {
  /// P changed (the direct coarse solver then redoes its symbolic analysis; implies
  /// updateCoarse).
  bool patternChanged = true;
  /// Recompute the Galerkin operators; without it the coarse operators of the last update are
  /// kept (stale), only A0 is new.
  bool updateCoarse = true;
  /// A0 has the pattern of the last call (AssembledMatrix::patternRevision unchanged): its block
  /// copy only refills values.
  bool fineSamePattern = false;
  /// Storage of the matrices the cycles multiply with (SymmetricBlockMatrix.h); A0 itself, used by the
  /// outer flexible CG and for residuals of the solve, stays in double.
  SymmetricBlockMatrix::Precision precision = SymmetricBlockMatrix::Precision::double_;
};

/// y = A x by any means (an assembled matrix, or the force fields' products without one).
using LinearOperator = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& y)>;

/// y = A x for the matrices the CG below takes.
inline void multiply(const SparseMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  y.noalias() = A * x;
}
inline void multiply(const SymmetricBlockMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  A.multiply(x, y);
}

class MultigridCycle {
 public:
  /// Keeps `A0` by reference (it must outlive the cycles), copies it into the 3 x 3 block
  /// storage the cycles multiply with, and computes the Galerkin operators
  /// A_{l+1} = P_l^T A_l P_l for the prolongations `P` (P[l]: level l + 1 to level l).
  void setOperators(const SparseMatrix& A0, const std::vector<SparseMatrix>& P,
                    const OperatorUpdate& update = {});

  /// Number of levels, fine one included.
  int levels() const { return int(m_P.size()) + 1; }
  /// The matrix of `level` as the cycles multiply with it.
  const SymmetricBlockMatrix& blocks(int level) const { return m_blocks[std::size_t(level)]; }
  const SparseMatrix& matrix(int level) const { return level == 0 ? *m_A0 : m_coarse[level - 1]; }

  /// One V-cycle on level `level` (0 = finest) from and into x.
  void vCycle(int level, Eigen::VectorXd& x, const Eigen::VectorXd& b,
              const CycleSettings& settings);
  /// One cycle of `kind` from zero: z = an approximate solution of A_0 z = r.
  void cycleFromZero(CycleKind kind, const Eigen::VectorXd& r, Eigen::VectorXd& z,
                     const CycleSettings& settings);

  /// Flexible CG on A x = b from x (Notay 2000, "Flexible conjugate gradients", SIAM J. Sci.
  /// Comput. 22: the Polak-Ribiere beta, since a cycle with CG smoothers is not a fixed linear
  /// operator), each iteration preconditioned by one cycle of `kind` from zero and one product
  /// with A (A may differ from the level-0 operator of the cycles, e.g. when they are stale or
  /// in single precision). Stops after `iterations` or at a relative residual
  /// ||b - A x|| / ||b|| <= tolerance. Returns the iterations; `residual` is the relative
  /// residual of the x returned.
  int flexibleConjugateGradient(const LinearOperator& A, const Eigen::VectorXd& b,
                                Eigen::VectorXd& x, int iterations, double tolerance,
                                CycleKind kind, const CycleSettings& settings, double& residual);
  /// The same with an assembled A.
  int flexibleConjugateGradient(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                int iterations, double tolerance, CycleKind kind,
                                const CycleSettings& settings, double& residual) {
    return flexibleConjugateGradient(
        [&A](const Eigen::VectorXd& in, Eigen::VectorXd& out) { out.noalias() = A * in; }, b, x,
        iterations, tolerance, kind, settings, residual);
  }

  /// `iterations` CG iterations on A x = b from x (A: SparseMatrix or SymmetricBlockMatrix); stops
  /// earlier when ||r|| <= tolerance ||b|| or when p.Ap is not positive (a converged or singular
  /// direction). Returns the iterations and leaves in r the residual b - A x (updated
  /// recursively, as CG does).
  template <class Matrix>
  static int conjugateGradient(const Matrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                               int iterations, double tolerance, Eigen::VectorXd& r,
                               Eigen::VectorXd& p, Eigen::VectorXd& q) {
    // Coarse corrections and preconditioning start from zero: r = b without a product.
    if ((x.array() == 0).all()) {
      r = b;
    } else {
      multiply(A, x, q);
      r.noalias() = b - q;
    }
    const double stop = tolerance * tolerance * b.squaredNorm();
    double rho = r.squaredNorm();
    if (rho <= stop || rho == 0) return 0;
    p = r;
    int done = 0;
    while (done < iterations) {
      multiply(A, p, q);
      const double den = p.dot(q);
      if (!(den > 0)) break;
      const double alpha = rho / den;
      x += alpha * p;
      r -= alpha * q;
      ++done;
      const double rhoNext = r.squaredNorm();
      if (rhoNext <= stop) break;
      p = r + (rhoNext / rho) * p;
      rho = rhoNext;
    }
    return done;
  }

 private:
  /// b restricted to every level, the coarsest solved, then from coarse to fine: prolongation
  /// of the coarser result, then a V-cycle (full) or CG (cascadic) on the level.
  void nestedIteration(Eigen::VectorXd& x, const Eigen::VectorXd& b, const CycleSettings& settings,
                       CycleKind kind);
  void solveCoarsest(Eigen::VectorXd& x, const Eigen::VectorXd& b, const CycleSettings& settings);

  struct Work {
    Eigen::VectorXd r, p, q, residual, coarseRhs, coarseX;
  };
  const SparseMatrix* m_A0 = nullptr;
  std::vector<const SparseMatrix*> m_P;
  std::vector<SparseMatrix> m_PT;      ///< P_l^T, remade when the pattern changes
  SparseMatrix m_AP;                   ///< scratch: A_l P_l
  std::vector<SparseMatrix> m_coarse;  ///< A_1 ... A_L
  std::vector<SymmetricBlockMatrix> m_blocks;   ///< A_0 ... A_L in the storage the cycles multiply with
  std::vector<Work> m_work;            ///< per level
  std::vector<Eigen::VectorXd> m_fullRhs;
  Eigen::VectorXd m_r, m_z, m_d, m_q, m_previousR;  ///< flexible CG
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> m_direct;
  bool m_directAnalyzed = false;
  bool m_directFactorized = false;  ///< m_direct holds the factors of the current A_L
  SparseMatrix m_coarsestRegular;   ///< A_L with 1 on zero diagonals, for the direct solve
};

}  // namespace stroma::multigrid
