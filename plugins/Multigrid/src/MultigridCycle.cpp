// SPDX-License-Identifier: MIT
#include "MultigridCycle.h"

#include <cmath>

namespace stroma::multigrid {

void MultigridCycle::setOperators(const SparseMatrix& A0, const std::vector<SparseMatrix>& P,
                                  bool patternChanged) {
  m_A0 = &A0;
  m_P.clear();
  for (const SparseMatrix& p : P) m_P.push_back(&p);
  m_coarse.resize(P.size());
  m_work.resize(P.size() + 1);
  // P^T once per pattern (the Galerkin products and the restrictions use it).
  if (patternChanged || m_PT.size() != P.size()) {
    m_PT.resize(P.size());
    for (std::size_t l = 0; l < P.size(); ++l) m_PT[l] = P[l].transpose();
    m_directAnalyzed = false;
  }
  // Galerkin operators, finest to coarsest.
  for (std::size_t l = 0; l < P.size(); ++l) {
    const SparseMatrix& fine = l == 0 ? A0 : m_coarse[l - 1];
    m_AP = fine * P[l];
    m_coarse[l] = m_PT[l] * m_AP;
  }
}

int MultigridCycle::conjugateGradient(const SparseMatrix& A, const Eigen::VectorXd& b,
                                      Eigen::VectorXd& x, int iterations, double tolerance,
                                      Eigen::VectorXd& r, Eigen::VectorXd& p, Eigen::VectorXd& q) {
  r.noalias() = b - A * x;
  const double stop = tolerance * tolerance * b.squaredNorm();
  double rho = r.squaredNorm();
  if (rho <= stop || rho == 0) return 0;
  p = r;
  q.resize(b.size());
  int done = 0;
  while (done < iterations) {
    q.noalias() = A * p;
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

void MultigridCycle::solveCoarsest(Eigen::VectorXd& x, const Eigen::VectorXd& b,
                                   const CycleSettings& settings) {
  const int level = levels() - 1;
  const SparseMatrix& A = matrix(level);
  if (!settings.directCoarseSolve || level == 0) {
    Work& w = m_work[level];
    conjugateGradient(A, b, x, settings.coarseIterations, 1e-12, w.r, w.p, w.q);
    return;
  }
  // Coarse unknowns that interpolate only fixed points have a zero row: 1 on their diagonal.
  m_coarsestRegular = A;
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    if (m_coarsestRegular.coeff(i, i) == 0) m_coarsestRegular.coeffRef(i, i) = 1;
  if (!m_directAnalyzed) {
    m_direct.analyzePattern(m_coarsestRegular);
    m_directAnalyzed = true;
  }
  m_direct.factorize(m_coarsestRegular);
  if (m_direct.info() == Eigen::Success) {
    x = m_direct.solve(b);
  } else {
    Work& w = m_work[level];
    conjugateGradient(A, b, x, settings.coarseIterations, 1e-12, w.r, w.p, w.q);
  }
}

void MultigridCycle::vCycle(int level, Eigen::VectorXd& x, const Eigen::VectorXd& b,
                            const CycleSettings& settings) {
  if (level == levels() - 1) {
    solveCoarsest(x, b, settings);
    return;
  }
  Work& w = m_work[level];
  const SparseMatrix& A = matrix(level);
  const SparseMatrix& P = *m_P[level];
  // 1. pre-smoothing
  conjugateGradient(A, b, x, settings.smoothingIterations, 0.0, w.r, w.p, w.q);
  // 2. restriction of the residual
  w.residual.noalias() = b - A * x;
  w.coarseRhs.noalias() = m_PT[level] * w.residual;
  // 3. coarse correction from zero
  w.coarseX.setZero(P.cols());
  vCycle(level + 1, w.coarseX, w.coarseRhs, settings);
  // 4. prolongation of the correction, post-smoothing
  x.noalias() += P * w.coarseX;
  if (settings.postSmoothing)
    conjugateGradient(A, b, x, settings.smoothingIterations, 0.0, w.r, w.p, w.q);
}

void MultigridCycle::fullCycle(Eigen::VectorXd& x, const Eigen::VectorXd& b,
                               const CycleSettings& settings) {
  const int coarsest = levels() - 1;
  m_fullRhs.resize(levels());
  m_fullRhs[0] = b;
  for (int l = 0; l < coarsest; ++l) m_fullRhs[l + 1].noalias() = m_PT[l] * m_fullRhs[l];
  Eigen::VectorXd current = Eigen::VectorXd::Zero(m_fullRhs[coarsest].size());
  solveCoarsest(current, m_fullRhs[coarsest], settings);
  for (int l = coarsest - 1; l >= 0; --l) {
    Eigen::VectorXd finer = *m_P[l] * current;
    vCycle(l, finer, m_fullRhs[l], settings);
    current.swap(finer);
  }
  x = current;
}

}  // namespace stroma::multigrid
