// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "ProjectedGaussSeidel.h"
#include "SolverSupport.h"
#include "core/Data.h"
#include "core/DataTraits.h"

namespace stroma {

/// SOFA's GenericConstraintSolver (and its newer names BlockGaussSeidelConstraintSolver,
/// ProjectedGaussSeidelConstraintSolver, UnbuiltGaussSeidelConstraintSolver): the constraint
/// problem of Constraints.h by projected Gauss-Seidel over the groups of rows
/// (ProjectedGaussSeidel.h), or by the nonsmooth nonlinear conjugate gradient over those sweeps
/// (resolutionMethod NonsmoothNonlinearConjugateGradient; NNCGConstraintSolver), warm-started
/// with the last step's multipliers when the rows are the same in number. Reports its
/// iterations and error (outputs), and warns when it stops unconverged (the first time; later
/// ones are counted at the end).
class GenericConstraintSolver : public BaseConstraintSolver {
 protected:
  /// The default resolutionMethod (NNCGConstraintSolver's differs).
  const char* m_initialMethod = "ProjectedGaussSeidel";
  explicit GenericConstraintSolver(const char* method) : m_initialMethod(method) {}

 public:
  GenericConstraintSolver() = default;

  Data<int> d_maxIterations{this, "maxIterations", 1000, "Largest number of Gauss-Seidel sweeps.",
                            {.min = 1.0, .alias = "maxIt"}};
  Data<double> d_tolerance{this, "tolerance", 0.001,
                           "Convergence: no row's displacement changes by more than this in a "
                           "sweep.",
                           {.unit = "m", .min = 0.0}};
  Data<double> d_sor{this, "sor", 1.0, "Over-relaxation factor of the sweeps.",
                     {.min = 0.0, .max = 2.0}};
  Data<double> d_regularizationTerm{this, "regularizationTerm", 0.0,
                                    "Added to W's diagonal: a redundant or contradictory set of "
                                    "bilateral constraints becomes solvable, each one yielding "
                                    "by this compliance.",
                                    {.unit = "m/N", .min = 0.0}};
  Data<std::string> d_resolutionMethod{this, "resolutionMethod", m_initialMethod,
                                       "ProjectedGaussSeidel, UnbuiltGaussSeidel (the same "
                                       "sweeps here) or NonsmoothNonlinearConjugateGradient."};
  Data<int> d_currentIterations{this, "currentIterations", 0,
                                "Output: sweeps of the last solve.", {.output = true}};
  Data<double> d_currentError{this, "currentError", 0.0, "Output: error of the last solve.",
                              {.unit = "m", .output = true}};
  Data<std::vector<double>> d_constraintForces{this, "constraintForces", {},
                                               "Output: the multipliers of the last solve (one "
                                               "per constraint row).",
                                               {.unit = "N", .output = true}};

  void init() override;
  void cleanup() override;
  ConstraintSolveReport solve(const Eigen::MatrixXd& W, const Eigen::VectorXd& violation,
                              std::span<const ConstraintGroup> groups,
                              Eigen::VectorXd& lambda) override;

 private:
  Eigen::VectorXd m_last;  // the last multipliers, for the warm start
  lagrangian::SolveCounts m_counts;
  bool m_conjugateGradient = false;
};

/// SOFA's NNCGConstraintSolver: GenericConstraintSolver with the nonsmooth nonlinear conjugate
/// gradient (ProjectedGaussSeidel.h): the projected Gauss-Seidel sweeps accelerated by a
/// Fletcher-Reeves momentum, restarted when it stops helping.
class NNCGConstraintSolver final : public GenericConstraintSolver {
 public:
  NNCGConstraintSolver() : GenericConstraintSolver("NonsmoothNonlinearConjugateGradient") {}
};

}  // namespace stroma
