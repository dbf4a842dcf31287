// SPDX-License-Identifier: MIT
// The condensation of nested hexahedra (plugins/NonUniformFEM/src/HexahedronCondensation.h):
// a full homogeneous parent condensed from 1 or 2 levels of children equals the directly
// integrated parent (K and M, seed 001 ch. 4 sec. 3); a parent with one full child has a
// non-uniform nodal stiffness, largest at that child's corner; the transfer functions.
#include "HexahedronCondensation.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "ImageMaterial.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "TransferFunction.h"

namespace stroma::fem {
namespace {

/// Nested levels of a parent cut `depth` times in 2 x 2 x 2: levels[0] the finest. Each cell of
/// level k has children 8 c + q in level k - 1 (all present unless `only` picks one child q of
/// every parent).
std::vector<sparsegrid::FinerLevel> nestedLevels(int depth, int only = -1) {
  std::vector<sparsegrid::FinerLevel> levels(depth);
  std::size_t parents = 1;
  for (int k = depth - 1; k >= 0; --k) {
    levels[k].parentsChildren.resize(parents);
    for (std::size_t p = 0; p < parents; ++p)
      for (int q = 0; q < 8; ++q)
        levels[k].parentsChildren[p][q] =
            (only < 0 || q == only) ? Index(8 * p + q) : kInvalidIndex;
    parents *= 8;
  }
  return levels;
}

/// A parallelepiped: the unit cube's corners mapped by A, then translated.
HexahedronVectors parallelepiped(const Eigen::Matrix3d& A, const Eigen::Vector3d& t) {
  HexahedronVectors X;
  for (int i = 0; i < 8; ++i)
    X.col(i) = A * (0.5 * (hexahedronReferenceCorner(i) + Eigen::Vector3d::Ones())) + t;
  return X;
}

std::vector<HexahedronVectors> testShapes() {
  Eigen::Matrix3d box = Eigen::Vector3d(0.3, 0.5, 0.7).asDiagonal();
  Eigen::Matrix3d sheared;
  sheared << 1.0, 0.2, -0.1, 0.1, 0.8, 0.3, -0.2, 0.1, 1.2;
  return {parallelepiped(box, Eigen::Vector3d(2, -1, 5)),
          parallelepiped(sheared, Eigen::Vector3d(-3, 1, 0.5))};
}

TEST(HexahedronCondensation, ChildInterpolationIsThePartitionOfUnityAtTheChildsCorners) {
  for (int q = 0; q < 8; ++q) {
    const Matrix8d L = computeChildInterpolation(q);
    EXPECT_LT((L.rowwise().sum() - Vector8d::Ones()).norm(), 1e-15);
    // The child's corner q is the parent's corner q; its opposite corner the parent's centre.
    EXPECT_NEAR(L(q, q), 1.0, 1e-15);
    const int opposite = q < 4 ? (q + 2) % 4 + 4 : (q - 4 + 2) % 4;
    EXPECT_LT((L.row(opposite) - Vector8d::Constant(0.125).transpose()).norm(), 1e-15) << q;
  }
}

class FullParent : public ::testing::TestWithParam<int> {};

TEST_P(FullParent, EqualsTheDirectlyIntegratedParentToRoundOff) {
  const int depth = GetParam();
  const double E = 3e4, nu = 0.3, rho = 1100;
  const auto levels = nestedLevels(depth);
  const auto material = [&](Index) { return CellMaterial{1.0, E, rho}; };
  const Matrix6d C = computeElasticityMatrix(computeLameParameters(E, nu));
  for (const HexahedronVectors& X : testShapes()) {
    Matrix24d direct;
    ASSERT_EQ(computeHexahedronStiffness(X, C, direct), ElementStatus::ok);
    const Matrix8d directMass = computeHexahedronConsistentMass(X, rho);
    CondensedHexahedron condensed;
    ASSERT_EQ(condenseHexahedron(X, 0, levels, material, nu, condensed), ElementStatus::ok);
    const double kError = (condensed.stiffness - direct).norm() / direct.norm();
    const double mError = (condensed.mass - directMass).norm() / directMass.norm();
    std::printf("[ condensed ] %d level(s): |K - Ke| / |Ke| = %.1e, |M - Me| / |Me| = %.1e\n",
                depth, kError, mError);
    EXPECT_LT(kError, 1e-13) << depth;
    EXPECT_LT(mError, 1e-13) << depth;
    EXPECT_NEAR(condensed.mass.sum(), rho * computeHexahedronVolume(X),
                1e-12 * condensed.mass.sum());
  }
}

INSTANTIATE_TEST_SUITE_P(HexahedronCondensation, FullParent, ::testing::Values(1, 2, 3));

TEST(HexahedronCondensation, WithoutFinerLevelsTheCellIsOneElementWeightedByItsFraction) {
  const double E = 500, nu = 0.25, rho = 7, fraction = 0.37;
  const HexahedronVectors X = testShapes()[1];
  CondensedHexahedron condensed;
  ASSERT_EQ(condenseHexahedron(
                X, 0, {},
                [&](Index) {
                  return CellMaterial{fraction, E, rho};
                },
                nu, condensed),
            ElementStatus::ok);
  Matrix24d direct;
  computeHexahedronStiffness(X, computeElasticityMatrix(computeLameParameters(E, nu)), direct);
  EXPECT_LT((condensed.stiffness - fraction * direct).norm(), 1e-14 * direct.norm());
  EXPECT_LT((condensed.mass - fraction * computeHexahedronConsistentMass(X, rho)).norm(),
            1e-14 * condensed.mass.norm());
}

/// The six rigid motions of the rest shape X (three translations, three small rotations).
Eigen::Matrix<double, 24, 6> rigidModes(const HexahedronVectors& X) {
  Eigen::Matrix<double, 24, 6> modes = Eigen::Matrix<double, 24, 6>::Zero();
  for (int i = 0; i < 8; ++i)
    for (int a = 0; a < 3; ++a) {
      modes(3 * i + a, a) = 1;
      Eigen::Vector3d axis = Eigen::Vector3d::Zero();
      axis[a] = 1;
      modes.block<3, 1>(3 * i, 3 + a) = axis.cross(Eigen::Vector3d(X.col(i)));
    }
  return modes;
}

TEST(HexahedronCondensation, OneFullChildGivesANonUniformNodalStiffnessLargestAtItsCorner) {
  const double E = 1e4, nu = 0.3, rho = 1000;
  const HexahedronVectors X = testShapes()[0];
  for (int depth : {1, 2}) {
    for (int q = 0; q < 8; ++q) {
      SCOPED_TRACE(testing::Message() << "depth " << depth << ", child " << q);
      // depth 1: the child at corner q; depth 2: its own child at corner q (1/64 of the cell).
      const auto levels = nestedLevels(depth, q);
      CondensedHexahedron c;
      ASSERT_EQ(condenseHexahedron(
                    X, 0, levels,
                    [&](Index) {
                      return CellMaterial{1, E, rho};
                    },
                    nu, c),
                ElementStatus::ok);
      const Matrix24d& K = c.stiffness;
      EXPECT_LT((K - K.transpose()).norm(), 1e-15 * K.norm());
      // Rigid motions cost nothing; the other 18 modes are stiff (the child is a full element
      // and the parent's trilinear field restricted to it has no other zero-energy mode).
      EXPECT_LT((K * rigidModes(X)).norm(), 1e-11 * K.norm() * X.norm());
      const Eigen::SelfAdjointEigenSolver<Matrix24d> eigen(K);
      EXPECT_GT(eigen.eigenvalues()[6], 1e-8 * eigen.eigenvalues()[23]);
      EXPECT_GT(eigen.eigenvalues()[0], -1e-12 * eigen.eigenvalues()[23]);
      // Nodal stiffness (trace of the diagonal 3 x 3 block): largest at corner q, smallest at
      // the opposite corner, and decreasing with the number of axes separating a node from q.
      std::array<double, 4> byDistance{1e300, 1e300, 1e300, 1e300}, maxByDistance{};
      for (int i = 0; i < 8; ++i) {
        const int d =
            int((hexahedronReferenceCorner(i) - hexahedronReferenceCorner(q)).cwiseAbs().sum() / 2);
        const double trace = K.block<3, 3>(3 * i, 3 * i).trace();
        byDistance[d] = std::min(byDistance[d], trace);
        maxByDistance[d] = std::max(maxByDistance[d], trace);
      }
      for (int d = 1; d < 4; ++d) EXPECT_GT(byDistance[d - 1], maxByDistance[d]) << d;
      // Mass: rho times the child's volume, most of it at corner q.
      const double childVolume = computeHexahedronVolume(X) / std::pow(8.0, depth);
      EXPECT_NEAR(c.mass.sum(), rho * childVolume, 1e-12 * rho * childVolume);
      Eigen::Index heaviest;
      c.mass.rowwise().sum().maxCoeff(&heaviest);
      EXPECT_EQ(heaviest, q);
    }
  }
}

TEST(HexahedronCondensation, EmptyChildrenContributeNothingAndFractionsWeight) {
  // Children 0 and 6 full, 3 at 40 %, the rest empty: the sum of the three one-child
  // condensations with their weights.
  const double E = 2e3, nu = 0.2, rho = 900;
  const HexahedronVectors X = testShapes()[1];
  auto levels = nestedLevels(1);
  for (int q : {1, 2, 4, 5, 7}) levels[0].parentsChildren[0][q] = kInvalidIndex;
  const auto material = [&](Index c) { return CellMaterial{c == 3 ? 0.4 : 1.0, E, rho}; };
  CondensedHexahedron together;
  ASSERT_EQ(condenseHexahedron(X, 0, levels, material, nu, together), ElementStatus::ok);
  Matrix24d K = Matrix24d::Zero();
  Matrix8d M = Matrix8d::Zero();
  for (int q : {0, 3, 6}) {
    CondensedHexahedron alone;
    condenseHexahedron(X, 0, nestedLevels(1, q), material, nu, alone);
    K += alone.stiffness;
    M += alone.mass;
  }
  EXPECT_LT((together.stiffness - K).norm(), 1e-14 * K.norm());
  EXPECT_LT((together.mass - M).norm(), 1e-14 * M.norm());
  EXPECT_NEAR(together.mass.sum(), rho * 2.4 / 8 * computeHexahedronVolume(X),
              1e-12 * together.mass.sum());
}

TEST(HexahedronCondensation, DegenerateFinestCellIsReported) {
  HexahedronVectors flat = testShapes()[0];
  flat.row(2).setZero();  // zero thickness
  CondensedHexahedron c;
  EXPECT_EQ(condenseHexahedron(
                flat, 0, nestedLevels(1), [](Index) { return CellMaterial{}; }, 0.3, c),
            ElementStatus::degenerate);
}

}  // namespace
}  // namespace stroma::fem

namespace stroma::nonuniform {
namespace {

TEST(TransferFunction, IsPiecewiseLinearAndConstantBeyondItsEnds) {
  std::string why;
  const std::vector<double> pairs{0, 1000, 100, 3000, 200, 3500};
  const auto f = TransferFunction::parse(pairs, 0.0, true, why);
  ASSERT_TRUE(f) << why;
  EXPECT_DOUBLE_EQ((*f)(-5), 1000);
  EXPECT_DOUBLE_EQ((*f)(0), 1000);
  EXPECT_DOUBLE_EQ((*f)(25), 1500);
  EXPECT_DOUBLE_EQ((*f)(100), 3000);
  EXPECT_DOUBLE_EQ((*f)(150), 3250);
  EXPECT_DOUBLE_EQ((*f)(1e6), 3500);
}

TEST(TransferFunction, RefusesBadTablesWithTheReason) {
  std::string why;
  const std::vector<double> odd{0, 1, 2};
  EXPECT_FALSE(TransferFunction::parse(odd, 0.0, true, why));
  EXPECT_NE(why.find("3 numbers"), std::string::npos) << why;
  const std::vector<double> decreasing{5, 1, 2, 3};
  EXPECT_FALSE(TransferFunction::parse(decreasing, 0.0, true, why));
  EXPECT_NE(why.find("increasing"), std::string::npos) << why;
  const std::vector<double> negative{0, 1000, 255, -5};
  EXPECT_FALSE(TransferFunction::parse(negative, 0.0, true, why));
  EXPECT_NE(why.find("-5 at image value 255"), std::string::npos) << why;
  const std::vector<double> zero{0, 0, 1, 10};
  EXPECT_FALSE(TransferFunction::parse(zero, 0.0, true, why));
  EXPECT_TRUE(TransferFunction::parse(zero, 0.0, false, why)) << why;  // a zero density is fine
}

}  // namespace
}  // namespace stroma::nonuniform

namespace stroma::nonuniform {
namespace {

TEST(MeanImageValue, AveragesTheVoxelsCentredInTheCellElseTakesTheNearest) {
  image::VolumeImage volume;
  volume.size = {4, 4, 4};
  volume.spacing = Vec3d(1, 2, 0.5);
  volume.origin = Vec3d(10, 20, 30);  // centre of voxel (0, 0, 0)
  volume.values.resize(64);
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) volume.at(i, j, k) = i + 10 * j + 100 * k;
  // Centres of voxels 1..2 on each axis: the mean of a linear field is its value at the middle.
  const Vec3d lower = volume.voxelCenter(1, 1, 1) - 0.5 * volume.spacing;
  EXPECT_DOUBLE_EQ(meanImageValue(volume, lower, lower + 2 * volume.spacing), 1.5 + 15 + 150);
  // A cell smaller than a voxel, no centre inside: the voxel nearest to its centre.
  const Vec3d inside = volume.voxelCenter(2, 1, 3) + 0.2 * volume.spacing;
  EXPECT_DOUBLE_EQ(meanImageValue(volume, inside, inside + 0.1 * volume.spacing), 2 + 10 + 300);
  // Outside the image: the nearest voxel on its border.
  EXPECT_DOUBLE_EQ(meanImageValue(volume, Vec3d(-100, -100, -100), Vec3d(-99, -99, -99)), 0);
}

}  // namespace
}  // namespace stroma::nonuniform
