// SPDX-License-Identifier: MIT
// Names the degree of freedom behind a row of the assembled system, for the messages of the
// direct solvers (a failed pivot or a NaN is reported where the user can look for it).
#pragma once

#include <Eigen/Sparse>
#include <cmath>
#include <string>

#include "simulation/MechanicalOperations.h"
#include "simulation/MechanicalState.h"

namespace stroma {

/// "point 12, component 1 of /root/Beam/dofs" for row 37 of mop's assembled system.
inline std::string describeSystemRow(const MechanicalOperations& mop, std::size_t row) {
  std::size_t offset = 0;
  for (const BaseMechanicalState* state : mop.independentStates()) {
    const std::size_t rows = state->matrixSize();
    if (row < offset + rows) {
      const auto dimension = static_cast<std::size_t>(state->derivDimension());
      const std::size_t local = row - offset;
      return "point " + std::to_string(local / dimension) + ", component " +
             std::to_string(local % dimension) + " of " + state->path();
    }
    offset += rows;
  }
  return "row " + std::to_string(row);
}

/// The first NaN or infinite entry of A (row and column), if any.
inline bool findNonFiniteEntry(const Eigen::SparseMatrix<double>& A, std::size_t& row,
                               std::size_t& col) {
  for (Eigen::Index k = 0; k < A.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator e(A, k); e; ++e)
      if (!std::isfinite(e.value())) {
        row = static_cast<std::size_t>(e.row());
        col = static_cast<std::size_t>(e.col());
        return true;
      }
  return false;
}

/// The error text for such an entry.
inline std::string describeNonFiniteEntry(const MechanicalOperations& mop, std::size_t row,
                                          std::size_t col) {
  return "the system matrix has a NaN or infinite entry at the row of " +
         describeSystemRow(mop, row) + " and the column of " + describeSystemRow(mop, col) +
         ": a force field or a mass computed it (diverged state, or invalid parameters)";
}

}  // namespace stroma
