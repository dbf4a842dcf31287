// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace stroma {

/// The compliance of constraint rows through a sparse L D L^T factorization,
///   W += factor J A^-1 J^T,   P A P^T = L D L^T,
/// as factor Y^T Y with Y = D^-1/2 L^-1 P J^T: forward substitutions only, each on the columns
/// of L its right-hand side reaches. A row of J touches a few degrees of freedom (a contact: a
/// vertex or a triangle), so L^-1 P J^T_r is non-zero only on the paths from those dofs to the
/// root of the elimination tree (Gilbert and Peierls 1988; Davis 2006, "Direct Methods for
/// Sparse Linear Systems", sections 3.2 and 4.1): each solve visits those columns only, and the
/// rows of a contact, which share their columns, are solved together (SIMD lanes). When J
/// touches fewer dofs than it has rows (three rows per contact on a vertex), the right-hand
/// sides are those dofs' unit vectors instead: X = E^T A^-1 E, then W += factor J X J^T. The
/// rows reached are gathered into a dense block and W (or X) gets its symmetric rank-k product.
/// Measured on SOFA's fallingBeamLagrangianCollision.scn: bench/README.md.
///
/// The buffers are kept between calls (vectors keep their capacity, the gathered block only
/// grows); the J X J^T temporaries are resized when the number of columns changes.
class LdltCompliance {
 public:
  using Factor = Eigen::SparseMatrix<double>;  // L: unit lower triangular, column-major
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  static constexpr int kLanes = 4;  ///< right-hand sides solved together

  /// Takes a new factorization's structure: the elimination tree is the first row below the
  /// diagonal of each column of L (rows sorted within a column, as up-looking factorization
  /// stores them).
  void setFactor(const Factor& L);

  /// W += factor J A^-1 J^T. `permutation`: the position in the factorization of each row of
  /// A (P's indices; empty for none); D: the pivots. False (W untouched) when a pivot reached
  /// is not positive (A not positive definite).
  bool add(const Factor& L, const Eigen::VectorXd& D, const Eigen::VectorXi& permutation,
           const RowMatrix& J, double factor, Eigen::MatrixXd& W);

 private:
  using Block = Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
  bool solve(const Factor& L, const Eigen::VectorXd& D, const Eigen::VectorXi& permutation);
  Block gatherBlock();

  // Elimination tree and per-dof marks (sized by setFactor).
  std::vector<int> m_parent;   // -1 at a root
  std::vector<int> m_mark;     // first right-hand side of the last group that reached a column
  std::vector<int> m_slot;     // row of the gathered block of each reached dof, or -1
  std::vector<int> m_column;   // index among the columns J touches, or -1
  std::vector<int> m_path, m_stack;  // one path up the tree; a group's reach, at the stack's end
  std::vector<double> m_work;  // kLanes right-hand sides / solutions per dof
  // Right-hand sides (sparse, columns of A), their groups, and what they reached.
  std::vector<int> m_columns, m_rhsStart, m_rhsIndex, m_groupStart;
  std::vector<double> m_rhsValue;
  std::vector<int> m_reached, m_reachStart, m_reachIndex;
  std::vector<double> m_reachValue;
  Eigen::MatrixXd m_storage;   // the gathered block's storage (grows only)
  // J X J^T when solving by columns.
  Eigen::MatrixXd m_X, m_XJt;
  RowMatrix m_Jc;
  std::vector<Eigen::Triplet<double>> m_triplets;
};

}  // namespace stroma
