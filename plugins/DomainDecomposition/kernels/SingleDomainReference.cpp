// SPDX-License-Identifier: MIT
#include "DomainDecomposition/kernels/SingleDomainReference.h"

#include <algorithm>

#include "Precomputed/kernels/LinearStiffnessAssembly.h"

namespace stroma::domaindecomposition {

SparseMatrix extractNodeBlock(const RowMajorMatrix& K, const std::vector<int>& nodes,
                              std::size_t pointCount) {
  std::vector<int> local(pointCount, -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) local[nodes[i]] = static_cast<int>(i);
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const int row = 3 * nodes[i] + c;
      for (RowMajorMatrix::InnerIterator it(K, row); it; ++it) {
        const int j = local[it.col() / 3];
        if (j >= 0)
          entries.emplace_back(static_cast<int>(3 * i) + c, 3 * j + it.col() % 3, it.value());
      }
    }
  SparseMatrix block(3 * nodes.size(), 3 * nodes.size());
  block.setFromTriplets(entries.begin(), entries.end());
  return block;
}

bool solveSingleDomain(const ElasticProblem& problem, const Loads& loads, Eigen::VectorXd& u,
                       std::string& error) {
  SparseMatrix K;
  std::vector<precomputed::TetrahedronNodes> tetrahedra(problem.tetrahedra.begin(),
                                                        problem.tetrahedra.end());
  if (!precomputed::assembleLinearStiffness(problem.points, tetrahedra, problem.youngModulus,
                                            problem.poissonRatio, K, error))
    return false;
  const std::size_t n = problem.points.size();
  std::vector<char> held(n, 0), active(n, 0);
  for (int p : problem.fixedNodes) held[p] = 1;
  for (int p : loads.imposedNodes) held[p] = 1;
  for (const TetrahedronNodes& t : problem.tetrahedra)
    for (std::uint32_t p : t) active[p] = 1;
  u = Eigen::VectorXd::Zero(3 * n);
  for (std::size_t i = 0; i < loads.imposedNodes.size(); ++i)
    u.segment<3>(3 * loads.imposedNodes[i]) = loads.imposedDisplacements[i];
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * n);
  for (std::size_t i = 0; i < loads.forceNodes.size(); ++i)
    f.segment<3>(3 * loads.forceNodes[i]) += loads.forces[i];
  f -= K * u;  // the imposed displacements move the free nodes
  std::vector<int> freeNodes;
  for (std::size_t p = 0; p < n; ++p)
    if (!held[p] && active[p]) freeNodes.push_back(static_cast<int>(p));
  const RowMajorMatrix rows = K;
  const SparseMatrix A = extractNodeBlock(rows, freeNodes, n);
  Eigen::VectorXd b(3 * freeNodes.size());
  for (std::size_t i = 0; i < freeNodes.size(); ++i)
    b.segment<3>(3 * i) = f.segment<3>(3 * freeNodes[i]);
  Eigen::SimplicialLDLT<SparseMatrix> factor(A);
  if (factor.info() != Eigen::Success || (factor.vectorD().array() <= 0).any()) {
    error = "the stiffness of the whole mesh is singular (no fixed node, or a piece with none)";
    return false;
  }
  const Eigen::VectorXd x = factor.solve(b);
  for (std::size_t i = 0; i < freeNodes.size(); ++i)
    u.segment<3>(3 * freeNodes[i]) = x.segment<3>(3 * i);
  return true;
}

double computeMeanEdgeLength(const std::vector<Vec3>& points,
                             const std::vector<TetrahedronNodes>& tetrahedra) {
  double sum = 0;
  std::size_t count = 0;
  for (const TetrahedronNodes& t : tetrahedra)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        sum += (points[t[i]] - points[t[j]]).norm();
        ++count;
      }
  return count ? sum / static_cast<double>(count) : 0.0;
}

DisplacementError compareDisplacements(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  DisplacementError error;
  const Eigen::Index n = u.size() / 3;
  for (Eigen::Index p = 0; p < n; ++p) {
    const double d = (u.segment<3>(3 * p) - v.segment<3>(3 * p)).norm();
    error.max = std::max(error.max, d);
    error.mean += d;
  }
  if (n) error.mean /= static_cast<double>(n);
  return error;
}

}  // namespace stroma::domaindecomposition
