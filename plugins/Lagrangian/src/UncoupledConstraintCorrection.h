// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Data.h"
#include "simulation/Constraints.h"

namespace stroma {

/// SOFA's UncoupledConstraintCorrection: each degree of freedom of the solver's states answers
/// a constraint force alone, with compliance c (m/N per unit of the solver's position factor):
///   W += positionFactor H diag(c) H^T,   dx = positionFactor diag(c) H^T lambda,
///   dv = velocityFactor diag(c) H^T lambda,
/// the ODE solver's factors (Constraints.h: h^2 and h for implicit Euler). c is `compliance`
/// (one value for every degree of freedom, or one per degree of freedom), or else 1 / (the row
/// sum of the mass matrix) of each degree of freedom: the inverse of a lumped mass. Exact for a
/// free body under a lumped mass and symplectic Euler; for an elastic body it leaves out the
/// stiffness (the points answer as if unattached), which LinearSolverConstraintCorrection
/// includes.
class UncoupledConstraintCorrection final : public BaseConstraintCorrection {
 public:
  Data<std::vector<double>> d_compliance{this, "compliance", {},
                                         "Compliance (1 / mass) of every degree of freedom: one "
                                         "value, one per degree of freedom, or empty for the "
                                         "inverse of the lumped mass.",
                                         {.min = 0.0}};

  void addCompliance(MechanicalOperations& mop, const ConstraintResponse& response,
                     const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                     Eigen::MatrixXd& W) override;
  void applyCorrection(MechanicalOperations& mop, const ConstraintResponse& response,
                       const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                       const Eigen::VectorXd& lambda) override;

 private:
  bool computeCompliance(MechanicalOperations& mop);

  Eigen::VectorXd m_c;  // per system degree of freedom
  Eigen::VectorXd m_correction;
};

}  // namespace stroma
