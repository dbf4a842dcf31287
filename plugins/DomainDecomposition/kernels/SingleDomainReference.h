// SPDX-License-Identifier: MIT
// The single-domain static solution that the hybrid model converges to, and the measures of
// the seed's figures 5.3 to 5.9 (nodal error normalised by the edge length).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "DomainDecomposition/kernels/HybridDecomposition.h"

namespace stroma::domaindecomposition {

/// The block K[nodes, nodes] (3m x 3m, in the order of `nodes`) of a node-major stiffness of
/// `pointCount` nodes.
SparseMatrix extractNodeBlock(const RowMajorMatrix& K, const std::vector<int>& nodes,
                              std::size_t pointCount);

/// The single-domain static solution (direct sparse LDL^T of K with the fixed and imposed
/// nodes eliminated), the reference of the hybrid model. False and `error` when singular.
bool solveSingleDomain(const ElasticProblem& problem, const Loads& loads, Eigen::VectorXd& u,
                       std::string& error);

/// Mean length of the edges of the tetrahedra (m), the seed's unit of error.
double computeMeanEdgeLength(const std::vector<Vec3>& points,
                             const std::vector<TetrahedronNodes>& tetrahedra);

/// Largest and mean nodal distance |u_i - v_i| (m) between two displacement fields.
struct DisplacementError {
  double max = 0;
  double mean = 0;
};
DisplacementError compareDisplacements(const Eigen::VectorXd& u, const Eigen::VectorXd& v);

}  // namespace stroma::domaindecomposition
