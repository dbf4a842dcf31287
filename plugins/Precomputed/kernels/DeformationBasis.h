// SPDX-License-Identifier: MIT
// The deformation basis of the precomputed quasi-static linear model (Cotin, Delingette,
// Ayache 1999; seed 000, chapter 2 section 2.1): for linear elasticity K u = f, the response to
// a unit force on each degree of freedom of a chosen set of "basis" nodes is computed once,
// and any load on those nodes is then a superposition of these responses.
//
// Notation: n nodes, K the assembled small-strain stiffness (3n x 3n, N/m, node-major dofs
// x0 y0 z0 x1 ...), F the fixed dofs (Dirichlet u = 0), k basis nodes b_0 .. b_{k-1}.
//
//   Column 3j + c of B = K_F^-1 e_{3 b_j + c}      (m/N)
//
// where K_F is K with the rows and columns of F replaced by the identity (fixed dofs then stay
// at zero, and a unit force on a fixed dof moves nothing: its column is zero). B is stored
// dense, column-major, 3r x 3k, for r "row nodes" (every node by default, or a subset such as
// the surface: restrictedTo). Memory 72 r k bytes (1000 nodes, 614 basis nodes: 44 MB).
//
// Superposition (forces f_j on basis nodes):     u = sum_j B_j f_j                  O(r m)
// Imposed displacements d on m basis nodes M (Cotin's "displacement" boundary condition):
//   B_MM r = d - B_MF f     (3m x 3m, symmetric positive definite: a block of K_F^-1)
//   u = B_M r + B_F f,      r = the forces the imposed nodes must receive (reaction forces)
// B_MM is factorised once per set M and kept until M changes, so a step costs O(m^2 + r m).
// At an imposed node, K u = r + f (the external force plus the reaction).
//
// Errors (singular K, a node out of range, an imposed node that is not a basis node) are
// returned as messages; nothing throws or aborts. Not thread-safe: the B_MM factorisation
// cache is mutable state.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>
#include <string>
#include <vector>

namespace stroma::precomputed {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Vec3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using VectorXd = Eigen::VectorXd;
using MatrixXd = Eigen::MatrixXd;

class DeformationBasis {
 public:
  /// Whether compute() needs fixed dofs: a stiffness K does (its rigid motions are singular);
  /// a system with mass, M + h^2 K (a constraint correction's compliance), needs none.
  enum class FixedDofs { required, optional };

  /// Factorises K_F once (Eigen's SimplicialLDLT) and solves for the 3k columns. `fixedDofs`:
  /// dof indices 3 node + c. `basisNodes`: distinct node indices in [0, n). Returns nullopt
  /// with `error` set when K is not square 3n x 3n, a dof or node is out of range or repeated,
  /// there is no fixed dof while `rule` requires some, or K_F is singular or indefinite (too
  /// few fixed dofs, a node outside every element). K may be any symmetric positive definite
  /// matrix once its fixed dofs are removed (the columns are then those of K_F^-1).
  static std::optional<DeformationBasis> compute(const SparseMatrix& K,
                                                 const std::vector<int>& fixedDofs,
                                                 const std::vector<int>& basisNodes,
                                                 std::string& error,
                                                 FixedDofs rule = FixedDofs::required);

  /// A basis from stored columns (a cache file): `columns` is 3 rowNodes.size() x 3
  /// basisNodes.size(), `fixedColumns` flags the columns of fixed dofs (3 basisNodes.size()).
  /// Checks the sizes and ranges only.
  static std::optional<DeformationBasis> fromColumns(int nodeCount, std::vector<int> rowNodes,
                                                     std::vector<int> basisNodes,
                                                     std::vector<char> fixedColumns,
                                                     MatrixXd columns, std::string& error);

  /// The same basis keeping only the rows of `rowNodes` (every basis node must be one of them,
  /// so that imposed displacements can still be solved). nullopt and `error` otherwise.
  std::optional<DeformationBasis> restrictedTo(const std::vector<int>& rowNodes,
                                               std::string& error) const;

  int nodeCount() const { return m_nodeCount; }
  /// Nodes whose displacement the rows give, in row order (u has 3 rowNodes().size() entries).
  const std::vector<int>& rowNodes() const { return m_rowNodes; }
  const std::vector<int>& basisNodes() const { return m_basisNodes; }
  /// 3r x 3k, column 3j + c = displacement of the row nodes for a unit force (1 N) in
  /// direction c on basis node j (m/N).
  const MatrixXd& columns() const { return m_columns; }
  /// 1 for the columns of fixed dofs (zero columns), 0 otherwise (3k entries).
  const std::vector<char>& fixedColumns() const { return m_fixedColumns; }
  /// Position of `node` in basisNodes(), or -1.
  int basisIndex(int node) const;
  /// Position of `node` in rowNodes(), or -1.
  int rowIndex(int node) const;

  /// u (3r) = displacement of the row nodes for forces (N) on basis nodes (superposition).
  /// false and `error` when a node is not a basis node or the sizes differ.
  bool displacementFromForces(const std::vector<int>& nodes, const std::vector<Vec3>& forces,
                              VectorXd& u, std::string& error) const;

  /// u (3r) for imposed displacements d (m) on basis nodes `nodes`, plus optional forces on
  /// other basis nodes; `reactions` receives the force (N) each imposed node needs. A fixed
  /// dof of an imposed node keeps u = 0: a non-zero imposed value there is an error. The
  /// factorisation of B_MM is kept while `nodes` is unchanged.
  bool displacementFromImposed(const std::vector<int>& nodes, const std::vector<Vec3>& d,
                               VectorXd& u, std::vector<Vec3>& reactions, std::string& error,
                               const std::vector<int>& forceNodes = {},
                               const std::vector<Vec3>& forces = {}) const;

  /// The 3 x 3 compliance block (m/N): displacement of row node i for a unit force on basis
  /// node j (node indices). Zero when either is unknown.
  Matrix3 compliance(int i, int j) const;

  /// Number of times B_MM was factorised (for tests: a second step with the same imposed
  /// nodes does not factorise again).
  int imposedFactorizationCount() const { return m_imposedFactorizations; }

 private:
  bool prepareImposed(const std::vector<int>& nodes, std::string& error) const;

  int m_nodeCount = 0;
  std::vector<int> m_rowNodes;
  std::vector<int> m_basisNodes;
  std::vector<int> m_basisIndexOfNode;  ///< n entries, -1 when not a basis node
  std::vector<int> m_rowIndexOfNode;    ///< n entries, -1 when not a row node
  std::vector<char> m_fixedColumns;
  MatrixXd m_columns;

  // Cache of the imposed-displacement system for the last set of imposed nodes.
  mutable bool m_imposedValid = false;
  mutable std::vector<int> m_imposedNodes;
  mutable std::vector<int> m_imposedFreeDofs;  ///< basis-column indices of the free imposed dofs
  mutable Eigen::LDLT<MatrixXd> m_imposedSystem;
  mutable int m_imposedFactorizations = 0;
  mutable VectorXd m_rhs, m_reaction;
};

}  // namespace stroma::precomputed
