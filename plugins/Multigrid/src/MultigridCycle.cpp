// SPDX-License-Identifier: MIT
#include "MultigridCycle.h"

#include <cmath>

namespace stroma::multigrid {

void MultigridCycle::setOperators(const SparseMatrix& A0, const std::vector<SparseMatrix>& P,
                                  const OperatorUpdate& update) {
  m_A0 = &A0;
  m_P.clear();
  for (const SparseMatrix& p : P) m_P.push_back(&p);
  m_coarse.resize(P.size());
  m_blocks.resize(P.size() + 1);
  m_work.resize(P.size() + 1);
  bool updateCoarse = update.updateCoarse;
  const bool patternChanged = update.patternChanged || m_PT.size() != P.size();
  // P^T once per pattern (the Galerkin products and the restrictions use it).
  if (patternChanged) {
    m_PT.resize(P.size());
    for (std::size_t l = 0; l < P.size(); ++l) m_PT[l] = P[l].transpose();
    m_directAnalyzed = false;
    updateCoarse = true;
  }
  const bool precisionChanged = m_blocks[0].precision() != update.precision;
  m_blocks[0].assign(A0, update.precision, update.fineSamePattern && !precisionChanged);
  if (!updateCoarse) {
    if (!precisionChanged) return;
    for (std::size_t l = 0; l < P.size(); ++l)
      m_blocks[l + 1].assign(m_coarse[l], update.precision, false);
    return;
  }
  m_directFactorized = false;
  // Galerkin operators, finest to coarsest. Their patterns follow from those of A0 and P alone
  // (Eigen's sparse product keeps structural zeros): unchanged when both are.
  const bool sameCoarsePatterns = !patternChanged && update.fineSamePattern && !precisionChanged;
  for (std::size_t l = 0; l < P.size(); ++l) {
    const SparseMatrix& fine = l == 0 ? A0 : m_coarse[l - 1];
    m_AP = fine * P[l];
    m_coarse[l] = m_PT[l] * m_AP;
    m_blocks[l + 1].assign(m_coarse[l], update.precision, sameCoarsePatterns);
  }
}

void MultigridCycle::solveCoarsest(Eigen::VectorXd& x, const Eigen::VectorXd& b,
                                   const CycleSettings& settings) {
  const int level = levels() - 1;
  const SparseMatrix& A = matrix(level);
  if (!settings.directCoarseSolve || level == 0) {
    Work& w = m_work[level];
    conjugateGradient(blocks(level), b, x, settings.coarseIterations, 1e-12, w.r, w.p, w.q);
    return;
  }
  // Factorized once per operator update (every cycle of every solve until the next update
  // uses the same factors).
  if (!m_directFactorized) {
    // Coarse unknowns that interpolate only fixed points have a zero row: 1 on their diagonal.
    m_coarsestRegular = A;
    for (Eigen::Index i = 0; i < A.rows(); ++i)
      if (m_coarsestRegular.coeff(i, i) == 0) m_coarsestRegular.coeffRef(i, i) = 1;
    if (!m_directAnalyzed) {
      m_direct.analyzePattern(m_coarsestRegular);
      m_directAnalyzed = true;
    }
    m_direct.factorize(m_coarsestRegular);
    m_directFactorized = true;
  }
  if (m_direct.info() == Eigen::Success) {
    x = m_direct.solve(b);
  } else {
    Work& w = m_work[level];
    conjugateGradient(blocks(level), b, x, settings.coarseIterations, 1e-12, w.r, w.p, w.q);
  }
}

void MultigridCycle::vCycle(int level, Eigen::VectorXd& x, const Eigen::VectorXd& b,
                            const CycleSettings& settings) {
  if (level == levels() - 1) {
    solveCoarsest(x, b, settings);
    return;
  }
  Work& w = m_work[level];
  const SymmetricBlockMatrix& A = blocks(level);
  const SparseMatrix& P = *m_P[level];
  // 1. pre-smoothing; CG leaves the residual b - A x in w.r (updated recursively, which is
  // the true residual to round-off after a few iterations), so the restriction needs no
  // further product with A.
  conjugateGradient(A, b, x, settings.smoothingAt(level), 0.0, w.r, w.p, w.q);
  // 2. restriction of the residual
  w.coarseRhs.noalias() = m_PT[level] * w.r;
  // 3. coarse correction from zero
  w.coarseX.setZero(P.cols());
  vCycle(level + 1, w.coarseX, w.coarseRhs, settings);
  // 4. prolongation of the correction, post-smoothing
  x.noalias() += P * w.coarseX;
  if (settings.postSmoothing)
    conjugateGradient(A, b, x, settings.smoothingAt(level), 0.0, w.r, w.p, w.q);
}

void MultigridCycle::nestedIteration(Eigen::VectorXd& x, const Eigen::VectorXd& b,
                                     const CycleSettings& settings, CycleKind kind) {
  const int coarsest = levels() - 1;
  m_fullRhs.resize(levels());
  m_fullRhs[0] = b;
  for (int l = 0; l < coarsest; ++l) m_fullRhs[l + 1].noalias() = m_PT[l] * m_fullRhs[l];
  Eigen::VectorXd current = Eigen::VectorXd::Zero(m_fullRhs[coarsest].size());
  solveCoarsest(current, m_fullRhs[coarsest], settings);
  for (int l = coarsest - 1; l >= 0; --l) {
    Eigen::VectorXd finer = *m_P[l] * current;
    if (kind == CycleKind::full) {
      for (int c = 0; c < settings.cyclesAt(l); ++c) vCycle(l, finer, m_fullRhs[l], settings);
    } else {
      Work& w = m_work[l];
      conjugateGradient(blocks(l), m_fullRhs[l], finer, settings.smoothingAt(l), 0.0, w.r, w.p,
                        w.q);
    }
    current.swap(finer);
  }
  x = current;
}

void MultigridCycle::cycleFromZero(CycleKind kind, const Eigen::VectorXd& r, Eigen::VectorXd& z,
                                   const CycleSettings& settings) {
  z.setZero(r.size());
  switch (kind) {
    case CycleKind::V: vCycle(0, z, r, settings); break;
    case CycleKind::full:
    case CycleKind::cascadic: nestedIteration(z, r, settings, kind); break;
  }
}

int MultigridCycle::flexibleConjugateGradient(const LinearOperator& A, const Eigen::VectorXd& b,
                                              Eigen::VectorXd& x, int iterations, double tolerance,
                                              CycleKind kind, const CycleSettings& settings,
                                              double& residual) {
  const double normB = b.norm();
  if ((x.array() == 0).all()) {
    m_r = b;
  } else {
    A(x, m_q);
    m_r = b - m_q;
  }
  residual = normB > 0 ? m_r.norm() / normB : 0;
  if (normB == 0 || residual <= tolerance) return 0;
  cycleFromZero(kind, m_r, m_z, settings);
  m_d = m_z;
  double rz = m_r.dot(m_z);
  int done = 0;
  while (done < iterations) {
    A(m_d, m_q);
    const double den = m_d.dot(m_q);
    if (!(den > 0) || !(rz > 0)) break;  // converged to round-off, or not positive definite
    const double alpha = rz / den;
    x += alpha * m_d;
    m_previousR = m_r;
    m_r -= alpha * m_q;
    ++done;
    residual = m_r.norm() / normB;
    if (!std::isfinite(residual) || residual <= tolerance || done >= iterations) return done;
    cycleFromZero(kind, m_r, m_z, settings);
    // Polak-Ribiere: beta = z_{k+1} . (r_{k+1} - r_k) / (z_k . r_k).
    const double beta = m_z.dot(m_r - m_previousR) / rz;
    rz = m_r.dot(m_z);
    m_d = m_z + beta * m_d;
  }
  // Stopped early: the residual of the x returned.
  A(x, m_q);
  m_r = b - m_q;
  residual = m_r.norm() / normB;
  return done;
}

}  // namespace stroma::multigrid
