// SPDX-License-Identifier: MIT
// The deformation basis of the precomputed linear model against direct sparse solves of the
// same linear elasticity problem: forces by superposition, imposed displacements through the
// compliance of the imposed nodes, reaction forces = K u, Maxwell-Betti reciprocity, errors.
#include "Precomputed/kernels/DeformationBasis.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>

#include "Precomputed/kernels/LinearStiffnessAssembly.h"
#include "plugins/SolidMechanics/FemTestScenes.h"

namespace stroma::precomputed {
namespace {

// A 4 x 1 x 1 m bar of 8 x 2 x 2 hexahedra cut into tetrahedra (81 nodes), clamped at x = 0.
struct Bar {
  test::FemMesh mesh = test::makeBoxMesh(Vec3d(4, 1, 1), Vec3i(8, 2, 2));
  SparseMatrix K;
  std::vector<int> fixedDofs;
  std::vector<int> allNodes;
  Bar() {
    std::string error;
    EXPECT_TRUE(assembleLinearStiffness(mesh.points, mesh.tetrahedra, 1e6, 0.3, K, error)) << error;
    for (int i = 0; i < int(mesh.points.size()); ++i) {
      allNodes.push_back(i);
      if (mesh.points[size_t(i)].x() == 0)
        for (int c = 0; c < 3; ++c) fixedDofs.push_back(3 * i + c);
    }
  }
  int nodeCount() const { return int(mesh.points.size()); }
};

// Direct solve of K u = f with u = given values on `dirichletDofs` (a dof -> value map given as
// a full vector `prescribed`, used on those dofs only).
VectorXd solveDirect(const SparseMatrix& K, const std::vector<int>& dirichletDofs,
                     const VectorXd& prescribed, const VectorXd& f) {
  const auto n = K.rows();
  std::vector<char> isDirichlet(size_t(n), 0);
  for (int dof : dirichletDofs) isDirichlet[size_t(dof)] = 1;
  std::vector<int> freeIndex(size_t(n), -1);
  std::vector<int> freeDofs;
  for (int i = 0; i < n; ++i)
    if (!isDirichlet[size_t(i)]) {
      freeIndex[size_t(i)] = int(freeDofs.size());
      freeDofs.push_back(i);
    }
  const auto m = Eigen::Index(freeDofs.size());
  std::vector<Eigen::Triplet<double>> triplets;
  VectorXd rhs(m);
  for (Eigen::Index a = 0; a < m; ++a) rhs[a] = f[freeDofs[size_t(a)]];
  for (int col = 0; col < K.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const int r = freeIndex[size_t(it.row())];
      if (r < 0) continue;
      const int c = freeIndex[size_t(it.col())];
      if (c >= 0)
        triplets.emplace_back(r, c, it.value());
      else
        rhs[r] -= it.value() * prescribed[it.col()];
    }
  SparseMatrix Kff(m, m);
  Kff.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(Kff);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  const VectorXd uf = ldlt.solve(rhs);
  VectorXd u = VectorXd::Zero(n);
  for (int dof : dirichletDofs) u[dof] = prescribed[dof];
  for (Eigen::Index a = 0; a < m; ++a) u[freeDofs[size_t(a)]] = uf[a];
  return u;
}

double relativeError(const VectorXd& a, const VectorXd& b) { return (a - b).norm() / b.norm(); }

TEST(DeformationBasis, ForcesOnOneAndSeveralNodesEqualTheDirectSolve) {
  Bar bar;
  std::string error;
  auto basis = DeformationBasis::compute(bar.K, bar.fixedDofs, bar.allNodes, error);
  ASSERT_TRUE(basis) << error;
  const std::vector<std::vector<int>> nodeSets{{80}, {80, 44, 17, 62}};
  for (const auto& nodes : nodeSets) {
    std::vector<Vec3> forces;
    VectorXd f = VectorXd::Zero(bar.K.rows());
    for (size_t i = 0; i < nodes.size(); ++i) {
      forces.emplace_back(10.0 * double(i + 1), -20.0, 5.0 - double(i));
      f.segment<3>(3 * nodes[i]) += forces.back();
    }
    VectorXd u;
    ASSERT_TRUE(basis->displacementFromForces(nodes, forces, u, error)) << error;
    const VectorXd reference = solveDirect(bar.K, bar.fixedDofs, VectorXd::Zero(bar.K.rows()), f);
    EXPECT_LT(relativeError(u, reference), 1e-8) << nodes.size() << " nodes";
  }
}

TEST(DeformationBasis, ImposedDisplacementsEqualTheDirectDirichletSolve) {
  Bar bar;
  std::string error;
  auto basis = DeformationBasis::compute(bar.K, bar.fixedDofs, bar.allNodes, error);
  ASSERT_TRUE(basis) << error;
  for (int count : {1, 5, 20}) {
    // Free nodes spread over the bar (x > 0), with displacements of a few millimetres.
    std::vector<int> nodes;
    std::vector<Vec3> d;
    for (int node = 80; node >= 0 && int(nodes.size()) < count; node -= 3) {
      if (bar.mesh.points[size_t(node)].x() == 0) continue;
      nodes.push_back(node);
      d.emplace_back(1e-3 * std::sin(node), 2e-3 * std::cos(node), -1e-3);
    }
    ASSERT_EQ(int(nodes.size()), count);
    VectorXd u;
    std::vector<Vec3> reactions;
    ASSERT_TRUE(basis->displacementFromImposed(nodes, d, u, reactions, error)) << error;

    std::vector<int> dirichlet = bar.fixedDofs;
    VectorXd prescribed = VectorXd::Zero(bar.K.rows());
    for (size_t i = 0; i < nodes.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        dirichlet.push_back(3 * nodes[i] + c);
        prescribed[3 * nodes[i] + c] = d[i][c];
      }
    const VectorXd reference =
        solveDirect(bar.K, dirichlet, prescribed, VectorXd::Zero(bar.K.rows()));
    EXPECT_LT(relativeError(u, reference), 1e-8) << count << " imposed nodes";
    const VectorXd Ku = bar.K * reference;
    for (size_t i = 0; i < nodes.size(); ++i) {
      EXPECT_LT((u.segment<3>(3 * nodes[i]) - d[i]).norm(), 1e-10 * d[i].norm());
      EXPECT_LT((reactions[i] - Ku.segment<3>(3 * nodes[i])).norm(),
                1e-8 * Ku.segment(0, Ku.size()).cwiseAbs().maxCoeff())
          << "reaction at node " << nodes[i];
    }
  }
}

TEST(DeformationBasis, ImposedDisplacementsWithForcesOnOtherNodes) {
  Bar bar;
  std::string error;
  auto basis = DeformationBasis::compute(bar.K, bar.fixedDofs, bar.allNodes, error);
  ASSERT_TRUE(basis) << error;
  const std::vector<int> nodes{80, 40};
  const std::vector<Vec3> d{Vec3(0, 0, -0.01), Vec3(0.001, 0, 0)};
  const std::vector<int> forceNodes{60};
  const std::vector<Vec3> forces{Vec3(0, 500, 0)};
  VectorXd u;
  std::vector<Vec3> reactions;
  ASSERT_TRUE(basis->displacementFromImposed(nodes, d, u, reactions, error, forceNodes, forces))
      << error;
  std::vector<int> dirichlet = bar.fixedDofs;
  VectorXd prescribed = VectorXd::Zero(bar.K.rows()), f = VectorXd::Zero(bar.K.rows());
  for (size_t i = 0; i < nodes.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      dirichlet.push_back(3 * nodes[i] + c);
      prescribed[3 * nodes[i] + c] = d[i][c];
    }
  f.segment<3>(3 * 60) = forces[0];
  EXPECT_LT(relativeError(u, solveDirect(bar.K, dirichlet, prescribed, f)), 1e-8);
}

TEST(DeformationBasis, TheImposedSystemIsFactorisedOncePerSetOfNodes) {
  Bar bar;
  std::string error;
  auto basis = DeformationBasis::compute(bar.K, bar.fixedDofs, bar.allNodes, error);
  ASSERT_TRUE(basis) << error;
  VectorXd u;
  std::vector<Vec3> reactions;
  const std::vector<int> nodes{80, 70};
  for (double s : {0.001, 0.002, 0.003})
    ASSERT_TRUE(
        basis->displacementFromImposed(nodes, {Vec3(0, 0, s), Vec3(s, 0, 0)}, u, reactions, error));
  EXPECT_EQ(basis->imposedFactorizationCount(), 1);
  ASSERT_TRUE(basis->displacementFromImposed({80}, {Vec3(0, 0, 0.001)}, u, reactions, error));
  EXPECT_EQ(basis->imposedFactorizationCount(), 2);
}

TEST(DeformationBasis, ComplianceIsReciprocalAndRestrictionKeepsRows) {
  Bar bar;
  std::string error;
  auto basis = DeformationBasis::compute(bar.K, bar.fixedDofs, bar.allNodes, error);
  ASSERT_TRUE(basis) << error;
  // Maxwell-Betti: the displacement at i for a unit force at j is the transpose of j's for i.
  const Matrix3 Cij = basis->compliance(80, 33), Cji = basis->compliance(33, 80);
  EXPECT_LT((Cij - Cji.transpose()).norm(), 1e-10 * Cij.norm());
  EXPECT_GT(Cij.norm(), 0);
  EXPECT_EQ(basis->compliance(0, 80), Matrix3::Zero());  // node 0 is clamped

  const std::vector<int> rows{80, 33, 12, 5};
  std::string restrictError;
  EXPECT_FALSE(basis->restrictedTo(rows, restrictError));  // basis nodes would lose their rows
  EXPECT_NE(restrictError.find("no row"), std::string::npos) << restrictError;
  auto small = DeformationBasis::compute(bar.K, bar.fixedDofs, {80, 33}, error);
  ASSERT_TRUE(small) << error;
  auto restricted = small->restrictedTo(rows, error);
  ASSERT_TRUE(restricted) << error;
  EXPECT_EQ(restricted->compliance(12, 80), small->compliance(12, 80));
  VectorXd u, uAll;
  ASSERT_TRUE(restricted->displacementFromForces({80}, {Vec3(1, 2, 3)}, u, error));
  ASSERT_TRUE(small->displacementFromForces({80}, {Vec3(1, 2, 3)}, uAll, error));
  ASSERT_EQ(u.size(), 12);
  for (size_t i = 0; i < rows.size(); ++i)
    EXPECT_LT((u.segment<3>(3 * Eigen::Index(i)) - uAll.segment<3>(3 * rows[i])).norm(),
              1e-14 * uAll.norm());  // same columns, products vectorised differently
}

TEST(DeformationBasis, SingularStiffnessAndBadNodesAreReported) {
  Bar bar;
  std::string error;
  EXPECT_FALSE(DeformationBasis::compute(bar.K, {}, bar.allNodes, error));
  EXPECT_NE(error.find("no fixed degree of freedom"), std::string::npos) << error;
  // One clamped node leaves the rotations about it free.
  error.clear();
  EXPECT_FALSE(DeformationBasis::compute(bar.K, {0, 1, 2}, bar.allNodes, error));
  EXPECT_NE(error.find("singular"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(DeformationBasis::compute(bar.K, bar.fixedDofs, {3, 81}, error));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(DeformationBasis::compute(bar.K, {-1}, {3}, error));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;

  auto basis = DeformationBasis::compute(bar.K, bar.fixedDofs, {80, 0}, error);
  ASSERT_TRUE(basis) << error;
  VectorXd u;
  std::vector<Vec3> reactions;
  EXPECT_FALSE(basis->displacementFromForces({50}, {Vec3(1, 0, 0)}, u, error));
  EXPECT_NE(error.find("not a basis node"), std::string::npos) << error;
  EXPECT_FALSE(basis->displacementFromImposed({0}, {Vec3(1, 0, 0)}, u, reactions, error));
  EXPECT_NE(error.find("fixed"), std::string::npos) << error;
  // A clamped node with a zero imposed value is accepted: nothing moves there.
  EXPECT_TRUE(basis->displacementFromImposed({0, 80}, {Vec3::Zero(), Vec3(0, 0, 0.01)}, u,
                                             reactions, error))
      << error;
  EXPECT_NEAR(u[3 * 80 + 2], 0.01, 1e-12);
}

TEST(LinearStiffnessAssembly, BadMaterialAndElementsAreReported) {
  const test::FemMesh mesh = test::makeBoxMesh(Vec3d(1, 1, 1), Vec3i(1, 1, 1));
  SparseMatrix K;
  std::string error;
  EXPECT_FALSE(assembleLinearStiffness(mesh.points, mesh.tetrahedra, 1e5, 0.5, K, error));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
  auto tets = mesh.tetrahedra;
  tets[2][1] = 99;
  EXPECT_FALSE(assembleLinearStiffness(mesh.points, tets, 1e5, 0.3, K, error));
  EXPECT_NE(error.find("tetrahedron 2"), std::string::npos) << error;
  tets = mesh.tetrahedra;
  tets[3] = {0, 1, 2, 2};
  EXPECT_FALSE(assembleLinearStiffness(mesh.points, tets, 1e5, 0.3, K, error));
  EXPECT_NE(error.find("degenerate"), std::string::npos) << error;
  // The assembled matrix is symmetric and a rigid translation produces no force.
  ASSERT_TRUE(assembleLinearStiffness(mesh.points, mesh.tetrahedra, 1e5, 0.3, K, error));
  EXPECT_LT((SparseMatrix(K.transpose()) - K).norm(), 1e-12 * K.norm());
  VectorXd t(K.rows());
  for (Eigen::Index i = 0; i < t.size(); ++i) t[i] = i % 3 == 0 ? 1.0 : 0.5;
  EXPECT_LT((K * t).norm(), 1e-10 * K.norm());
}

}  // namespace
}  // namespace stroma::precomputed
