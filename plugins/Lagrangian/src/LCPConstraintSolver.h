// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "ProjectedGaussSeidel.h"
#include "SolverSupport.h"
#include "core/Data.h"

namespace stroma {

/// SOFA's LCPConstraintSolver: the contact problem as a linear complementarity problem with
/// Coulomb friction of coefficient `mu` for every contact (the scene's, not the models'),
/// solved by projected Gauss-Seidel (ProjectedGaussSeidel.h) from zero each step. Reports its
/// iterations and error, and warns when it stops unconverged.
class LCPConstraintSolver final : public BaseConstraintSolver {
 public:
  Data<double> d_tolerance{this, "tolerance", 0.001,
                           "Convergence: no row's displacement changes by more than this in a "
                           "sweep.",
                           {.unit = "m", .min = 0.0}};
  Data<int> d_maxIt{this, "maxIt", 1000, "Largest number of Gauss-Seidel sweeps.", {.min = 1.0}};
  Data<double> d_mu{this, "mu", 0.6, "Friction coefficient of every contact.", {.min = 0.0}};
  Data<int> d_currentIterations{this, "currentIterations", 0,
                                "Output: sweeps of the last solve.", {.output = true}};
  Data<double> d_currentError{this, "currentError", 0.0, "Output: error of the last solve.",
                              {.unit = "m", .output = true}};

  void init() override;
  void cleanup() override;
  ConstraintSolveReport solve(const Eigen::MatrixXd& W, const Eigen::VectorXd& violation,
                              std::span<const ConstraintGroup> groups,
                              Eigen::VectorXd& lambda) override;

 private:
  lagrangian::SolveCounts m_counts;
};

}  // namespace stroma
