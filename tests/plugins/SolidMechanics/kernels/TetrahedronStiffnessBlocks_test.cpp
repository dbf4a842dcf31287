// SPDX-License-Identifier: MIT
// TetrahedronStiffnessBlocks: the blocks are those of sum_e R_e Ke_e R_e^T (Ke from
// computeCorotationalTetrahedron, one Young modulus per element, full and deviatoric C), the
// product is that matrix's, and neither depends on how the rows are split.
#include "SolidMechanics/kernels/TetrahedronStiffnessBlocks.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "FemTestUtilities.h"
#include "SolidMechanics/kernels/VolumetricSplit.h"

namespace stroma::fem {
namespace {

using Tetrahedron = TetrahedronStiffnessBlocks::Tetrahedron;

/// Two cubes side by side, each split into 5 tetrahedra (12 points; points 0 and 11 share no
/// tetrahedron), their points moved by up to 0.1 m so that no two elements are alike.
struct Mesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<Tetrahedron> elements;
  Mesh() {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> noise(-0.1, 0.1);
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 2; ++y)
        for (int z = 0; z < 2; ++z)
          points.emplace_back(x + noise(rng), y + noise(rng), z + noise(rng));
    const auto p = [](int x, int y, int z) {
      return static_cast<std::uint32_t>(4 * x + 2 * y + z);
    };
    for (int c = 0; c < 2; ++c) {
      const std::uint32_t a = p(c, 0, 0), b = p(c + 1, 0, 0), d = p(c, 1, 0), e = p(c, 0, 1),
                          f = p(c + 1, 1, 0), g = p(c + 1, 0, 1), h = p(c, 1, 1),
                          k = p(c + 1, 1, 1);
      for (const Tetrahedron& t :
           {Tetrahedron{a, b, d, e}, Tetrahedron{b, f, d, k}, Tetrahedron{b, e, g, k},
            Tetrahedron{d, e, k, h}, Tetrahedron{b, d, e, k}})
        elements.push_back(t);
    }
  }
  TetrahedronVectors rest(std::size_t e) const {
    TetrahedronVectors X;
    for (int i = 0; i < 4; ++i) X.col(i) = points[elements[e][i]];
    return X;
  }
};

struct RotatedElements {
  std::vector<Eigen::Matrix3d> rotations;
  std::vector<TetrahedronRows> factors;
  Eigen::MatrixXd K;  // sum of R Ke R^T, dense
};

/// Element constants for moduli 1000 + 100 e, rotations at random, and the dense reference.
RotatedElements makeRotatedElements(const Mesh& mesh, const Matrix6d& unitC) {
  std::mt19937 rng(11);
  RotatedElements s;
  const auto n = static_cast<Eigen::Index>(3 * mesh.points.size());
  s.K = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const double E = 1000.0 + 100.0 * static_cast<double>(e);
    CorotationalTetrahedron element;
    EXPECT_EQ(computeCorotationalTetrahedron(mesh.rest(e), E * unitC, element), ElementStatus::ok);
    s.rotations.push_back(test::randomRotation(rng));
    s.factors.push_back(computeStiffnessFactor(element, E));
    const Matrix12d Ke = computeStiffness(element, s.rotations.back());
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        s.K.block<3, 3>(3 * mesh.elements[e][a], 3 * mesh.elements[e][b]) +=
            Ke.block<3, 3>(3 * a, 3 * b);
  }
  return s;
}

TetrahedronStiffnessBlocks fill(const Mesh& mesh, const RotatedElements& s,
                                const LameParameters& lame) {
  TetrahedronStiffnessBlocks blocks;
  blocks.setPattern(mesh.elements, mesh.points.size());
  blocks.rotateFactors(s.rotations, s.factors, 0, mesh.elements.size());
  blocks.fillUpperBlocks(lame, 0, mesh.points.size());
  blocks.fillLowerBlocks(0, mesh.points.size());
  return blocks;
}

class StiffnessBlocks : public ::testing::TestWithParam<bool> {};  // deviatoric C or full C

TEST_P(StiffnessBlocks, AreTheSumOfTheRotatedElementStiffnesses) {
  const LameParameters lame = computeLameParameters(1.0, 0.3);
  const Matrix6d unitC =
      GetParam() ? computeDeviatoricElasticityMatrix(lame) : computeElasticityMatrix(lame);
  const std::optional<LameParameters> found = findLameParameters(unitC);
  ASSERT_TRUE(found);
  const Mesh mesh;
  const RotatedElements s = makeRotatedElements(mesh, unitC);
  const TetrahedronStiffnessBlocks blocks = fill(mesh, s, *found);
  EXPECT_EQ(blocks.rowCount(), 12u);
  const double scale = s.K.cwiseAbs().maxCoeff();
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    for (std::size_t j = 0; j < mesh.points.size(); ++j) {
      const Eigen::Matrix3d expected = s.K.block<3, 3>(3 * i, 3 * j);
      EXPECT_LE((blocks.block(i, j) - expected).cwiseAbs().maxCoeff(), 1e-13 * scale)
          << "block " << i << ", " << j;
    }
  EXPECT_EQ(blocks.block(0, 11), Eigen::Matrix3d::Zero());  // no common tetrahedron

  // out += factor K v, whole or split in two row ranges: the same numbers.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<Eigen::Vector3d> v(mesh.points.size()), whole(v.size()), split(v.size());
  Eigen::VectorXd flat(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i] = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    whole[i] = split[i] = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    flat.segment<3>(3 * static_cast<Eigen::Index>(i)) = v[i];
  }
  const std::vector<Eigen::Vector3d> start = whole;
  blocks.multiply(v, whole, -0.7, 0, v.size());
  blocks.multiply(v, split, -0.7, 0, 5);
  blocks.multiply(v, split, -0.7, 5, v.size());
  const Eigen::VectorXd expected = -0.7 * (s.K * flat);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(whole[i], split[i]);
    EXPECT_LE((whole[i] - start[i] - expected.segment<3>(3 * static_cast<Eigen::Index>(i)))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-13 * scale);
  }
}

INSTANTIATE_TEST_SUITE_P(TetrahedronStiffnessBlocks, StiffnessBlocks, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "deviatoric" : "full"; });

TEST(TetrahedronStiffnessBlocks, FindsTheLameParametersOfIsotropicMatricesOnly) {
  const LameParameters lame = computeLameParameters(3000.0, 0.45);
  const auto full = findLameParameters(computeElasticityMatrix(lame));
  ASSERT_TRUE(full);
  EXPECT_NEAR(full->lambda, lame.lambda, 1e-12 * lame.lambda);
  EXPECT_NEAR(full->mu, lame.mu, 1e-12 * lame.mu);
  const auto deviatoric = findLameParameters(computeDeviatoricElasticityMatrix(lame));
  ASSERT_TRUE(deviatoric);
  EXPECT_NEAR(deviatoric->lambda, -2.0 / 3.0 * lame.mu, 1e-12 * lame.mu);
  EXPECT_NEAR(deviatoric->mu, lame.mu, 1e-12 * lame.mu);
  Matrix6d anisotropic = computeElasticityMatrix(lame);
  anisotropic(0, 0) *= 1.01;
  EXPECT_FALSE(findLameParameters(anisotropic));
  Matrix6d coupled = computeElasticityMatrix(lame);
  coupled(0, 4) = coupled(4, 0) = 0.01 * lame.mu;
  EXPECT_FALSE(findLameParameters(coupled));
}

}  // namespace
}  // namespace stroma::fem
