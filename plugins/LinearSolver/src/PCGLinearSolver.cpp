// SPDX-License-Identifier: MIT
#include "PCGLinearSolver.h"

#include <cmath>
#include <cstdio>

#include "core/Node.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Timing.h"

namespace stroma {

void PCGLinearSolver::init() {
  m_preconditioner = l_preconditioner.get();
  const std::string& name = d_preconditioners.value();
  if (!m_preconditioner && !name.empty() && node()) {
    m_preconditioner = dynamic_cast<LinearSolver*>(node()->findObject(name));
    if (!m_preconditioner)
      msgError("no linear solver named '" + name + "' in " + node()->path(), "preconditioners");
  }
  if (m_preconditioner == this) {
    msgError("a solver cannot precondition itself: link another linear solver "
             "(SparseLDLSolver)",
             "preconditioner");
    m_preconditioner = nullptr;
  }
  if (!m_preconditioner && l_preconditioner.path().empty() && name.empty())
    msgInfo("no preconditioner: plain conjugate gradient (link one with preconditioner=\"@...\")");
}

bool PCGLinearSolver::precondition(MechanicalOperations& mop, const MechanicalParams& mp, VecId z,
                                   VecId r) {
  const bool due = !m_refreshed || (d_buildPrecond.value() &&
                                    m_solvesSinceRefresh >= d_updateStep.value());
  // The first application of a solve that is due refreshes the preconditioner (its solve
  // assembles and factorizes A); the others reuse its last factorization.
  if (due || !m_preconditioner->solveWithLastMatrix(mop, z, r)) {
    const LinearSolveReport report = m_preconditioner->solve(mop, mp, z, r);
    m_refreshed = true;
    m_solvesSinceRefresh = 0;
    d_refreshes.setValue(d_refreshes.value() + 1);
    if (!report.converged) return false;
  }
  mop.projectResponse(z);
  return true;
}

LinearSolveReport PCGLinearSolver::solve(MechanicalOperations& mop, const MechanicalParams& mp,
                                         VecId x, VecId rhs) {
  ScopedPhase phase(mop.timing(), "pcg");
  ++m_solves;
  LinearSolveReport report;
  mop.vOp(x, VecId::null(), VecId::null(), 0.0);
  const double bb = mop.dot(rhs, rhs);
  if (bb == 0) {
    d_lastIterations.setValue(0);
    d_lastResidual.setValue(0.0);
    return report;
  }
  // x = 0: r = b. z = P r, or r itself without (or after a failure of) the preconditioner.
  bool preconditioned = m_preconditioner && d_usePrecond.value();
  const VecId r = mop.allocDeriv(), z = mop.allocDeriv(), p = mop.allocDeriv(),
              q = mop.allocDeriv();
  mop.vOp(r, rhs);
  const auto applyPreconditioner = [&] {
    if (preconditioned && !precondition(mop, mp, z, r)) preconditioned = false;
    if (!preconditioned) mop.vOp(z, r);
  };
  applyPreconditioner();
  mop.vOp(p, z);
  double rz = mop.dot(r, z);
  const double stop = d_tolerance.value() * bb;
  const int maxIterations = d_iterations.value();
  while (rz > stop && report.iterations < maxIterations) {
    mop.computeMBKdx(mp, q, p);
    mop.projectResponse(q);
    const double pq = mop.dot(p, q);
    if (!(pq > 0) || !std::isfinite(pq)) break;  // A (or P) not positive definite
    const double alpha = rz / pq;
    mop.vOp(x, x, p, alpha);
    mop.vOp(r, r, q, -alpha);
    applyPreconditioner();
    const double rzNext = mop.dot(r, z);
    mop.vOp(p, z, p, rzNext / rz);
    rz = rzNext;
    ++report.iterations;
  }
  ++m_solvesSinceRefresh;
  report.converged = rz <= stop;
  report.residual = mop.norm(r) / std::sqrt(bb);  // the ODE solvers' measure: ||r|| / ||b||
  mop.freeVec(q);
  mop.freeVec(p);
  mop.freeVec(z);
  mop.freeVec(r);

  d_lastIterations.setValue(report.iterations);
  d_lastResidual.setValue(report.residual);
  if (!report.converged && m_unconverged++ == 0) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "PCG stopped after %d iterations without converging: r.Pr / b.b = %.3g > "
                  "tolerance %.3g (relative residual %.3g)",
                  report.iterations, rz / bb, d_tolerance.value(), report.residual);
    msgWarning(std::string(text) +
                   " (raise iterations or refresh the preconditioner more often: update_step); "
                   "later ones are counted",
               "iterations");
  }
  return report;
}

void PCGLinearSolver::cleanup() {
  if (m_unconverged > 1)
    msgWarning("PCG did not converge in " + std::to_string(m_unconverged) + " of " +
                   std::to_string(m_solves) + " solves",
               "iterations");
}

}  // namespace stroma
