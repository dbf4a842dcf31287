// SPDX-License-Identifier: MIT
// The deviatoric / volumetric split and the element pieces of the locking-free options
// (VolumetricSplit.h): the split adds up to C, the mean-dilatation gradients reproduce linear
// fields, the mean-dilatation stiffness has no spurious zero-energy mode, and the corotated
// divergence is the trace of the strain.
#include "SolidMechanics/kernels/VolumetricSplit.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "FemTestUtilities.h"
#include "SolidMechanics/kernels/CorotationalTetrahedron.h"
#include "SolidMechanics/kernels/TrilinearHexahedron.h"

namespace stroma::fem {
namespace {

using test::distortedHexahedron;
using test::irregularTetrahedron;
using test::unitCube;

const Vector6d kDilatation = (Vector6d() << 1, 1, 1, 0, 0, 0).finished();

TEST(VolumetricSplit, DeviatoricPlusBulkIsTheElasticityMatrix) {
  for (double nu : {0.0, 0.3, 0.499}) {
    const LameParameters lame = computeLameParameters(1e6, nu);
    const Matrix6d C = computeElasticityMatrix(lame);
    const Matrix6d Cdev = computeDeviatoricElasticityMatrix(lame);
    const double kappa = computeBulkModulus(lame);
    EXPECT_NEAR(kappa, 1e6 / (3 * (1 - 2 * nu)), 1e-9 * kappa) << nu;
    EXPECT_LT((Cdev + kappa * kDilatation * kDilatation.transpose() - C).norm(), 1e-12 * C.norm())
        << nu;
    // A pure dilatation carries no deviatoric stress; shears carry mu, as in C.
    EXPECT_LT((Cdev * kDilatation).norm(), 1e-12 * C.norm()) << nu;
    EXPECT_EQ(Cdev(3, 3), lame.mu);
  }
}

TEST(VolumetricSplit, MeanGradientsReproduceLinearFields) {
  // On a box the mean gradients are the centre ones (det J constant).
  HexahedronVectors meanGradients, centre;
  double volume = 0, detJ = 0;
  const Eigen::Matrix3d A = (Eigen::Matrix3d() << 2, 0.3, 0.1, 0, 1.5, -0.2, 0, 0, 0.5).finished();
  ASSERT_EQ(computeHexahedronMeanGradients(A * unitCube(), meanGradients, volume),
            ElementStatus::ok);
  ASSERT_EQ(computeHexahedronGradients(A * unitCube(), Eigen::Vector3d::Zero(), centre, detJ),
            ElementStatus::ok);
  EXPECT_NEAR(volume, A.determinant(), 1e-13);
  EXPECT_LT((meanGradients - centre).norm(), 1e-13 * centre.norm());
  // On a distorted shape: sum_i x_i bbar_i^T is the (constant) gradient of a linear field x.
  const HexahedronVectors X = distortedHexahedron();
  ASSERT_EQ(computeHexahedronMeanGradients(X, meanGradients, volume), ElementStatus::ok);
  EXPECT_NEAR(volume, computeHexahedronVolume(X), 1e-14);
  const Eigen::Matrix3d G = (Eigen::Matrix3d() << 1, 2, -1, 0.5, 3, 0, -2, 1, 1).finished();
  EXPECT_LT(((G * X) * meanGradients.transpose() - G).norm(), 1e-12 * G.norm());
  EXPECT_LT(meanGradients.rowwise().sum().norm(), 1e-12);
}

/// Eigenvalues of a hexahedron's Ke: zero ones (rigid modes), and stiff ones (> 100 mu V: the
/// volumetric constraints, since kappa / mu = 5000 at nu = 0.4999).
struct ModeCount {
  int zero = 0, stiff = 0;
  bool positiveSemiDefinite = true;
};

ModeCount countModes(const Matrix24d& Ke, double mu, double volume) {
  const Eigen::SelfAdjointEigenSolver<Matrix24d> eigen(Ke);
  const double largest = eigen.eigenvalues()[23];
  ModeCount count;
  for (double value : eigen.eigenvalues()) {
    count.positiveSemiDefinite &= value > -1e-12 * largest;
    if (std::abs(value) < 1e-10 * largest) ++count.zero;
    if (value > 100 * mu * volume) ++count.stiff;
  }
  return count;
}

TEST(VolumetricSplit, MeanDilatationStiffnessHasOneVolumetricConstraint) {
  // Deviatoric part at 2 x 2 x 2 points plus kappa V bbar bbar^T: symmetric, positive
  // semi-definite, exactly 6 zero eigenvalues (no hourglass mode), and one stiff mode, where the
  // fully integrated element has one per independent Gauss-point constraint (7): volumetric
  // locking at the element level.
  const HexahedronVectors X = distortedHexahedron();
  const LameParameters lame = computeLameParameters(1e6, 0.4999);
  const double kappa = computeBulkModulus(lame);
  HexahedronVectors meanGradients;
  double volume = 0;
  ASSERT_EQ(computeHexahedronMeanGradients(X, meanGradients, volume), ElementStatus::ok);
  Matrix24d Ke;
  ASSERT_EQ(computeHexahedronStiffness(X, computeDeviatoricElasticityMatrix(lame), Ke),
            ElementStatus::ok);
  addMeanDilatationStiffness<8>(meanGradients, volume, kappa, Ke);
  EXPECT_LT((Ke - Ke.transpose()).norm(), 1e-12 * Ke.norm());
  const ModeCount reduced = countModes(Ke, lame.mu, volume);
  EXPECT_TRUE(reduced.positiveSemiDefinite);
  EXPECT_EQ(reduced.zero, 6);
  EXPECT_EQ(reduced.stiff, 1);
  ASSERT_EQ(computeHexahedronStiffness(X, computeElasticityMatrix(lame), Ke), ElementStatus::ok);
  const ModeCount full = countModes(Ke, lame.mu, volume);
  EXPECT_EQ(full.zero, 6);
  EXPECT_EQ(full.stiff, 7);
}

TEST(VolumetricSplit, CorotatedDivergenceIsTheTraceOfTheStrain) {
  const TetrahedronVectors X = irregularTetrahedron();
  CorotationalTetrahedron element;
  ASSERT_EQ(computeCorotationalTetrahedron(X, test::testElasticity(), element), ElementStatus::ok);
  TetrahedronVectors g;
  g.rightCols<3>() = element.restEdgesInverse.transpose();
  g.col(0) = -g.rightCols<3>().rowwise().sum();
  // x = Q (I + H) X + t: in the frame R = Q the divergence is tr(H).
  const Eigen::Matrix3d H = (Eigen::Matrix3d() << 1, 2, 0, -1, 3, 0.5, 0, 1, -2).finished() * 1e-3;
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, -1, 2).normalized()).toRotationMatrix();
  const TetrahedronVectors x =
      (Q * (Eigen::Matrix3d::Identity() + H) * X).colwise() + Eigen::Vector3d(3, -1, 2);
  EXPECT_NEAR(computeCorotatedDivergence(g, Q, x, X), H.trace(), 1e-15);
  // A differential: the linear change, translations ignored.
  const TetrahedronVectors dx = (Q * H * X).colwise() + Eigen::Vector3d(1, 1, 1);
  EXPECT_NEAR(computeCorotatedDivergence(g, Q, dx, TetrahedronVectors::Zero()), H.trace(), 1e-15);
}

}  // namespace
}  // namespace stroma::fem
