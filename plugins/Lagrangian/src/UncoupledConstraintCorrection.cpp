// SPDX-License-Identifier: MIT
#include "UncoupledConstraintCorrection.h"

#include "CorrectionSupport.h"
#include "core/Message.h"
#include "simulation/MechanicalOperations.h"

namespace stroma {

bool UncoupledConstraintCorrection::computeCompliance(MechanicalOperations& mop) {
  const auto n = static_cast<Eigen::Index>(mop.systemSize());
  const std::vector<double>& given = d_compliance.value();
  if (given.size() == 1) {
    m_c = Eigen::VectorXd::Constant(n, given[0]);
  } else if (!given.empty()) {
    if (static_cast<Eigen::Index>(given.size()) != n) {
      msgError("has " + std::to_string(given.size()) + " values for the " + std::to_string(n) +
                   " degrees of freedom of the solver's states: give one value, or one per "
                   "degree of freedom",
               "compliance");
      return false;
    }
    m_c = Eigen::Map<const Eigen::VectorXd>(given.data(), n);
  } else {
    // The row sums of M: M times ones.
    const Eigen::VectorXd diagonal = lagrangian::massRowSums(mop);
    m_c.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) m_c[i] = diagonal[i] > 0 ? 1.0 / diagonal[i] : 0.0;
  }
  // Fixed degrees of freedom do not move.
  std::vector<char> fixed;
  mop.fixedGlobalRows(fixed);
  for (Eigen::Index i = 0; i < n; ++i)
    if (fixed[static_cast<std::size_t>(i)]) m_c[i] = 0;
  return true;
}

void UncoupledConstraintCorrection::addCompliance(MechanicalOperations& mop,
                                                  const ConstraintResponse& response,
                                                  const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                                                  Eigen::MatrixXd& W) {
  if (!computeCompliance(mop)) return;
  W += response.positionFactor * (H * m_c.asDiagonal() * H.transpose());
}

void UncoupledConstraintCorrection::applyCorrection(MechanicalOperations& mop,
                                                    const ConstraintResponse& response,
                                                    const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                                                    const Eigen::VectorXd& lambda) {
  if (m_c.size() != static_cast<Eigen::Index>(mop.systemSize())) return;
  m_correction = m_c.asDiagonal() * (H.transpose() * lambda);
  lagrangian::moveStates(mop, response, m_correction);
}

}  // namespace stroma
