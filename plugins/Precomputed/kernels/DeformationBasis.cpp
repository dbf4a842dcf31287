// SPDX-License-Identifier: MIT
#include "Precomputed/kernels/DeformationBasis.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <vector>

namespace stroma::precomputed {
namespace {

// A pivot of the LDL^T factorisation below this fraction of K's largest diagonal entry is
// taken as zero: K_F is then singular (a rigid motion left free, a node outside every element).
constexpr double kSingularPivotRatio = 1e-10;

std::vector<int> makeIndexOfNode(int nodeCount, const std::vector<int>& nodes) {
  std::vector<int> indexOf(static_cast<size_t>(nodeCount), -1);
  for (size_t i = 0; i < nodes.size(); ++i) indexOf[static_cast<size_t>(nodes[i])] = int(i);
  return indexOf;
}

// Checks that `nodes` are distinct indices in [0, nodeCount); `what` names them in the message.
bool checkNodes(const std::vector<int>& nodes, int nodeCount, const char* what,
                std::string& error) {
  std::vector<char> seen(static_cast<size_t>(nodeCount), 0);
  for (int node : nodes) {
    if (node < 0 || node >= nodeCount) {
      error = std::string(what) + " node " + std::to_string(node) + " is out of range [0, " +
              std::to_string(nodeCount) + ")";
      return false;
    }
    if (seen[static_cast<size_t>(node)]) {
      error = std::string(what) + " node " + std::to_string(node) + " is listed twice";
      return false;
    }
    seen[static_cast<size_t>(node)] = 1;
  }
  return true;
}

}  // namespace

std::optional<DeformationBasis> DeformationBasis::compute(const SparseMatrix& K,
                                                          const std::vector<int>& fixedDofs,
                                                          const std::vector<int>& basisNodes,
                                                          std::string& error,
                                                          FixedDofs rule) {
  if (K.rows() != K.cols() || K.rows() % 3 != 0 || K.rows() == 0) {
    error = "the stiffness matrix is " + std::to_string(K.rows()) + " x " +
            std::to_string(K.cols()) + ", expected 3n x 3n with n > 0 nodes";
    return std::nullopt;
  }
  const int dofCount = int(K.rows());
  const int nodeCount = dofCount / 3;
  if (fixedDofs.empty() && rule == FixedDofs::required) {
    error =
        "no fixed degree of freedom: the stiffness matrix is singular (rigid motions are "
        "free); fix at least three non-aligned nodes";
    return std::nullopt;
  }
  std::vector<char> fixed(static_cast<size_t>(dofCount), 0);
  for (int dof : fixedDofs) {
    if (dof < 0 || dof >= dofCount) {
      error = "fixed dof " + std::to_string(dof) + " is out of range [0, " +
              std::to_string(dofCount) + ")";
      return std::nullopt;
    }
    fixed[static_cast<size_t>(dof)] = 1;
  }
  if (!checkNodes(basisNodes, nodeCount, "basis", error)) return std::nullopt;

  // K_F: rows and columns of fixed dofs replaced by the identity.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<size_t>(K.nonZeros()) + fixedDofs.size());
  double largestDiagonal = 0;
  for (int col = 0; col < K.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const auto row = static_cast<size_t>(it.row()), column = static_cast<size_t>(it.col());
      if (!std::isfinite(it.value())) {
        error = "the stiffness matrix has a non-finite entry at (" + std::to_string(row) + ", " +
                std::to_string(column) + ")";
        return std::nullopt;
      }
      if (row == column) largestDiagonal = std::max(largestDiagonal, std::abs(it.value()));
      if (!fixed[row] && !fixed[column]) triplets.emplace_back(int(row), int(column), it.value());
    }
  }
  // The identity is scaled to K's diagonal so that every pivot compares to the same threshold.
  const double scale = largestDiagonal > 0 ? largestDiagonal : 1.0;
  for (int dof = 0; dof < dofCount; ++dof)
    if (fixed[static_cast<size_t>(dof)]) triplets.emplace_back(dof, dof, scale);
  SparseMatrix KF(dofCount, dofCount);
  KF.setFromTriplets(triplets.begin(), triplets.end());

  Eigen::SimplicialLDLT<SparseMatrix> ldlt(KF);
  if (ldlt.info() != Eigen::Success) {
    error = "the LDL^T factorisation of the stiffness matrix failed";
    return std::nullopt;
  }
  const VectorXd D = ldlt.vectorD();
  const double threshold = kSingularPivotRatio * scale;
  for (int i = 0; i < dofCount; ++i) {
    if (!(D[i] > threshold)) {
      error = "the stiffness matrix with its fixed dofs is singular or indefinite (pivot " +
              std::to_string(D[i]) +
              "): a rigid motion is not fixed, or a node belongs to no "
              "element";
      return std::nullopt;
    }
  }

  // One solve per basis dof; the right-hand sides are unit vectors.
  const int k = int(basisNodes.size());
  DeformationBasis basis;
  basis.m_nodeCount = nodeCount;
  basis.m_rowNodes.resize(static_cast<size_t>(nodeCount));
  for (int i = 0; i < nodeCount; ++i) basis.m_rowNodes[static_cast<size_t>(i)] = i;
  basis.m_basisNodes = basisNodes;
  basis.m_fixedColumns.assign(static_cast<size_t>(3 * k), 0);
  MatrixXd rhs = MatrixXd::Zero(dofCount, 3 * k);
  for (int j = 0; j < k; ++j) {
    for (int c = 0; c < 3; ++c) {
      const int dof = 3 * basisNodes[static_cast<size_t>(j)] + c;
      if (fixed[static_cast<size_t>(dof)])
        basis.m_fixedColumns[static_cast<size_t>(3 * j + c)] = 1;
      else
        rhs(dof, 3 * j + c) = 1.0;
    }
  }
  basis.m_columns = ldlt.solve(rhs);
  // Fixed rows are exactly zero by construction of K_F; fixed columns have a zero right-hand side.
  basis.m_basisIndexOfNode = makeIndexOfNode(nodeCount, basis.m_basisNodes);
  basis.m_rowIndexOfNode = makeIndexOfNode(nodeCount, basis.m_rowNodes);
  return basis;
}

std::optional<DeformationBasis> DeformationBasis::fromColumns(
    int nodeCount, std::vector<int> rowNodes, std::vector<int> basisNodes,
    std::vector<char> fixedColumns, MatrixXd columns, std::string& error) {
  if (nodeCount <= 0) {
    error = "node count " + std::to_string(nodeCount) + " is not positive";
    return std::nullopt;
  }
  if (!checkNodes(rowNodes, nodeCount, "row", error) ||
      !checkNodes(basisNodes, nodeCount, "basis", error))
    return std::nullopt;
  const auto r = Eigen::Index(rowNodes.size()), k = Eigen::Index(basisNodes.size());
  if (columns.rows() != 3 * r || columns.cols() != 3 * k ||
      fixedColumns.size() != static_cast<size_t>(3 * k)) {
    error = "the basis is " + std::to_string(columns.rows()) + " x " +
            std::to_string(columns.cols()) + " with " + std::to_string(fixedColumns.size()) +
            " column flags, expected " + std::to_string(3 * r) + " x " + std::to_string(3 * k);
    return std::nullopt;
  }
  DeformationBasis basis;
  basis.m_nodeCount = nodeCount;
  basis.m_rowNodes = std::move(rowNodes);
  basis.m_basisNodes = std::move(basisNodes);
  basis.m_fixedColumns = std::move(fixedColumns);
  basis.m_columns = std::move(columns);
  basis.m_basisIndexOfNode = makeIndexOfNode(nodeCount, basis.m_basisNodes);
  basis.m_rowIndexOfNode = makeIndexOfNode(nodeCount, basis.m_rowNodes);
  for (int node : basis.m_basisNodes) {
    if (basis.m_rowIndexOfNode[static_cast<size_t>(node)] < 0) {
      error = "basis node " + std::to_string(node) +
              " has no row: imposed displacements on it "
              "could not be solved";
      return std::nullopt;
    }
  }
  return basis;
}

std::optional<DeformationBasis> DeformationBasis::restrictedTo(const std::vector<int>& rowNodes,
                                                               std::string& error) const {
  MatrixXd rows(3 * Eigen::Index(rowNodes.size()), m_columns.cols());
  for (size_t i = 0; i < rowNodes.size(); ++i) {
    const int node = rowNodes[i];
    const int row = node >= 0 && node < m_nodeCount ? rowIndex(node) : -1;
    if (row < 0) {
      error = "node " + std::to_string(node) + " has no row in this basis";
      return std::nullopt;
    }
    rows.middleRows<3>(3 * Eigen::Index(i)) = m_columns.middleRows<3>(3 * Eigen::Index(row));
  }
  return fromColumns(m_nodeCount, rowNodes, m_basisNodes, m_fixedColumns, std::move(rows), error);
}

int DeformationBasis::basisIndex(int node) const {
  return node >= 0 && node < m_nodeCount ? m_basisIndexOfNode[static_cast<size_t>(node)] : -1;
}

int DeformationBasis::rowIndex(int node) const {
  return node >= 0 && node < m_nodeCount ? m_rowIndexOfNode[static_cast<size_t>(node)] : -1;
}

bool DeformationBasis::displacementFromForces(const std::vector<int>& nodes,
                                              const std::vector<Vec3>& forces, VectorXd& u,
                                              std::string& error) const {
  if (nodes.size() != forces.size()) {
    error = std::to_string(nodes.size()) + " force nodes but " + std::to_string(forces.size()) +
            " forces";
    return false;
  }
  u.setZero(m_columns.rows());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const int j = basisIndex(nodes[i]);
    if (j < 0) {
      error = "node " + std::to_string(nodes[i]) +
              " is not a basis node: no force can be applied "
              "on it";
      return false;
    }
    u.noalias() += m_columns.middleCols<3>(3 * Eigen::Index(j)) * forces[i];
  }
  return true;
}

bool DeformationBasis::prepareImposed(const std::vector<int>& nodes, std::string& error) const {
  if (m_imposedValid && nodes == m_imposedNodes) return true;
  m_imposedValid = false;
  m_imposedNodes.clear();
  m_imposedFreeDofs.clear();
  std::vector<int> freeRows;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const int j = basisIndex(nodes[i]);
    if (j < 0) {
      error = "imposed node " + std::to_string(nodes[i]) + " is not a basis node";
      return false;
    }
    if (std::find(nodes.begin(), nodes.begin() + long(i), nodes[i]) != nodes.begin() + long(i)) {
      error = "imposed node " + std::to_string(nodes[i]) + " is listed twice";
      return false;
    }
    for (int c = 0; c < 3; ++c) {
      if (m_fixedColumns[static_cast<size_t>(3 * j + c)]) continue;
      m_imposedFreeDofs.push_back(3 * j + c);
      freeRows.push_back(3 * rowIndex(nodes[i]) + c);
    }
  }
  // B_MM: the compliance among the free imposed dofs, symmetric positive definite.
  const auto p = Eigen::Index(m_imposedFreeDofs.size());
  MatrixXd S(p, p);
  for (Eigen::Index a = 0; a < p; ++a)
    for (Eigen::Index b = 0; b < p; ++b)
      S(a, b) = m_columns(freeRows[size_t(a)], m_imposedFreeDofs[size_t(b)]);
  m_imposedSystem.compute(S);
  ++m_imposedFactorizations;
  if (m_imposedSystem.info() != Eigen::Success || !m_imposedSystem.isPositive()) {
    error = "the compliance among the imposed nodes is not positive definite";
    return false;
  }
  m_imposedNodes = nodes;
  m_imposedValid = true;
  m_rhs.resize(p);
  m_reaction.resize(p);
  return true;
}

bool DeformationBasis::displacementFromImposed(const std::vector<int>& nodes,
                                               const std::vector<Vec3>& d, VectorXd& u,
                                               std::vector<Vec3>& reactions, std::string& error,
                                               const std::vector<int>& forceNodes,
                                               const std::vector<Vec3>& forces) const {
  if (nodes.size() != d.size()) {
    error = std::to_string(nodes.size()) + " imposed nodes but " + std::to_string(d.size()) +
            " imposed displacements";
    return false;
  }
  if (!prepareImposed(nodes, error)) return false;
  // Forces first (u = B_F f), then the imposed dofs take what is missing: B_MM r = d - u_M.
  if (!displacementFromForces(forceNodes, forces, u, error)) return false;
  size_t a = 0;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const int j = basisIndex(nodes[i]);
    const int row = 3 * rowIndex(nodes[i]);
    for (int c = 0; c < 3; ++c) {
      if (m_fixedColumns[static_cast<size_t>(3 * j + c)]) {
        if (d[i][c] != 0) {
          error = "imposed node " + std::to_string(nodes[i]) + " is fixed in direction " +
                  std::to_string(c) + " but its imposed displacement there is not zero";
          return false;
        }
        continue;
      }
      m_rhs[Eigen::Index(a++)] = d[i][c] - u[row + c];
    }
  }
  m_reaction = m_imposedSystem.solve(m_rhs);
  reactions.assign(nodes.size(), Vec3::Zero());
  a = 0;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const int j = basisIndex(nodes[i]);
    for (int c = 0; c < 3; ++c) {
      if (m_fixedColumns[static_cast<size_t>(3 * j + c)]) continue;
      const double r = m_reaction[Eigen::Index(a++)];
      reactions[i][c] = r;
      u.noalias() += r * m_columns.col(3 * j + c);
    }
  }
  return true;
}

Matrix3 DeformationBasis::compliance(int i, int j) const {
  const int row = rowIndex(i), column = basisIndex(j);
  if (row < 0 || column < 0) return Matrix3::Zero();
  return m_columns.block<3, 3>(3 * Eigen::Index(row), 3 * Eigen::Index(column));
}

}  // namespace stroma::precomputed
