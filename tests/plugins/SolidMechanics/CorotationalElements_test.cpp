// SPDX-License-Identifier: MIT
// CorotationalElements on hexahedra: equal elements share one entry of the constants, and the
// forces, products, assembled K and energy stay those of one entry per element (the kernels
// called element by element) to round-off.
// On tetrahedra: the products through the stiffness blocks, which the products after the first
// at one linearization point use, are those of the element loop to round-off.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "FemTestScenes.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "SolidMechanics/src/CorotationalElements.h"
#include "core/ThreadPool.h"
#include "linalg/AssembledMatrix.h"

namespace stroma::fem {
// GoogleTest prints the parameters of SharedHexahedra with it (found by argument lookup).
void PrintTo(RotationMethod method, std::ostream* out) { *out << rotationMethodName(method); }
}  // namespace stroma::fem

namespace stroma::test {
namespace {

using Hexahedra = CorotationalElements<fem::CorotationalHexahedron>;
constexpr double kPoissonRatio = 0.45;

/// A 5 x 3 x 2 grid of cells 0.2 x 0.2333... x 0.15 m (spacings that binary floating point
/// does not hold exactly), translated far from the origin, so that the copies of the cell
/// differ in the last bits; element 0 has its outer corner moved (another shape) and element 7
/// its own Young modulus.
struct Grid {
  FemMesh mesh = makeBoxMesh(Vec3d(1.0, 0.7, 0.3), Vec3i(5, 3, 2));
  std::vector<double> youngModulus;
  Grid() {
    for (Vec3d& p : mesh.points) p += Vec3d(10.1, -3.7, 2.3);
    mesh.points[0] += Vec3d(-0.03, 0.01, -0.02);  // the corner of element 0 only
    youngModulus.assign(mesh.hexahedra.size(), 3000.0);
    youngModulus[7] = 5000.0;
  }
  std::vector<Hexahedra::Indices> elements() const {
    return {mesh.hexahedra.begin(), mesh.hexahedra.end()};
  }
};

/// Positions rotated by 0.4 rad about (1, 2, 3), translated and perturbed by 1 % of a cell.
std::vector<Vec3d> deformed(const std::vector<Vec3d>& rest) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-0.002, 0.002);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.4, Vec3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Vec3d> x;
  for (const Vec3d& p : rest)
    x.push_back(Q * p + Vec3d(0.1, 0.2, -0.3) + Vec3d(noise(rng), noise(rng), noise(rng)));
  return x;
}

/// What the force field computed before sharing: each element's own constants, the kernels
/// called element by element, K = R_N Ke R_N^T as a dense product.
struct Unshared {
  std::vector<fem::CorotationalHexahedron> constants;
  std::vector<Eigen::Matrix3d> rotations;
  Eigen::VectorXd force, dForce;
  Eigen::MatrixXd K;  // df/dx = -K
  double energy = 0;
};

Unshared computeUnshared(const Grid& grid, const std::vector<Vec3d>& x,
                         const std::vector<Vec3d>& dx, fem::RotationMethod method) {
  const auto n = static_cast<Eigen::Index>(3 * grid.mesh.points.size());
  Unshared r;
  r.force = r.dForce = Eigen::VectorXd::Zero(n);
  r.K = Eigen::MatrixXd::Zero(n, n);
  const auto gather = [](const std::vector<Vec3d>& v, const std::array<unsigned, 8>& nodes) {
    fem::HexahedronVectors result;
    for (int i = 0; i < 8; ++i) result.col(i) = v[nodes[i]];
    return result;
  };
  for (std::size_t e = 0; e < grid.mesh.hexahedra.size(); ++e) {
    const auto& nodes = grid.mesh.hexahedra[e];
    fem::CorotationalHexahedron element;
    const fem::Matrix6d C = fem::computeElasticityMatrix(
        fem::computeLameParameters(grid.youngModulus[e], kPoissonRatio));
    EXPECT_EQ(fem::computeCorotationalHexahedron(gather(grid.mesh.points, nodes), C, element),
              fem::ElementStatus::ok);
    const fem::HexahedronVectors xe = gather(x, nodes);
    const Eigen::Matrix3d R = fem::computeRotation(method, element, xe);
    const fem::HexahedronVectors f = fem::computeForce(element, R, xe);
    const fem::HexahedronVectors df = fem::computeDForce(element, R, gather(dx, nodes));
    fem::Matrix24d RN = fem::Matrix24d::Zero();
    for (int i = 0; i < 8; ++i) RN.block<3, 3>(3 * i, 3 * i) = R;
    const fem::Matrix24d Ke = RN * element.stiffness * RN.transpose();
    for (int i = 0; i < 8; ++i) {
      r.force.segment<3>(3 * nodes[i]) += f.col(i);
      r.dForce.segment<3>(3 * nodes[i]) += df.col(i);
      for (int j = 0; j < 8; ++j)
        r.K.block<3, 3>(3 * nodes[i], 3 * nodes[j]) += Ke.block<3, 3>(3 * i, 3 * j);
    }
    r.energy += fem::computeEnergy(element, R, xe);
    r.constants.push_back(element);
    r.rotations.push_back(R);
  }
  return r;
}

Eigen::VectorXd flatten(const std::vector<Vec3d>& v) {
  Eigen::VectorXd result(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i) result.segment<3>(3 * i) = v[i];
  return result;
}

Hexahedra makeHexahedra(const Grid& grid, const ThreadPool& pool) {
  Hexahedra hexahedra;
  const auto elements = grid.elements();
  hexahedra.setElements(elements, grid.mesh.points.size());
  const auto report =
      hexahedra.computeConstants(grid.mesh.points, grid.youngModulus, kPoissonRatio, pool);
  EXPECT_TRUE(report.degenerate.empty());
  EXPECT_TRUE(report.inverted.empty());
  return hexahedra;
}

TEST(CorotationalElements, EqualHexahedraShareOneEntryOfConstants) {
  const ThreadPool pool(1);
  const Grid grid;
  const Hexahedra hexahedra = makeHexahedra(grid, pool);
  // The 28 copies of the cell, element 0 (another shape), element 7 (another modulus).
  EXPECT_EQ(hexahedra.distinctConstantCount(), 3u);
  EXPECT_EQ(&hexahedra.constant(1), &hexahedra.constant(29));
  EXPECT_NE(&hexahedra.constant(0), &hexahedra.constant(1));
  EXPECT_NE(&hexahedra.constant(7), &hexahedra.constant(1));
  // Each element keeps its own rest positions.
  EXPECT_EQ(hexahedra.restPositions(29).col(0), grid.mesh.points[grid.mesh.hexahedra[29][0]]);

  // A shape change of 1e-10 of a cell is not round-off: the element gets its own entry.
  Grid moved;
  moved.mesh.points[5] += Vec3d(2e-11, 0, 0);  // the x = max corner of the bottom row: element 4
  EXPECT_EQ(makeHexahedra(moved, pool).distinctConstantCount(), 4u);
}

class SharedHexahedra : public ::testing::TestWithParam<fem::RotationMethod> {};

TEST_P(SharedHexahedra, GiveTheForcesProductsMatrixAndEnergyOfUnsharedConstants) {
  const fem::RotationMethod method = GetParam();
  const ThreadPool pool(1);
  const Grid grid;
  Hexahedra hexahedra = makeHexahedra(grid, pool);
  const std::vector<Vec3d> x = deformed(grid.mesh.points);
  std::vector<Vec3d> dx(x.size());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (Vec3d& d : dx) d = Vec3d(unit(rng), unit(rng), unit(rng));
  const Unshared expected = computeUnshared(grid, x, dx, method);

  std::vector<Vec3d> f(x.size(), Vec3d::Zero()), df(x.size(), Vec3d::Zero());
  hexahedra.addForce(method, x, f, pool);
  hexahedra.addDForce(dx, df, 1.0, pool);
  AssembledMatrix matrix;
  matrix.begin(3 * x.size());
  hexahedra.addKToMatrix(matrix, 0, 1.0, pool);
  matrix.finish();
  const Eigen::MatrixXd K = -Eigen::MatrixXd(matrix.matrix());

  // Round-off: the cell copies differ by a few eps |X| (|X| ~ 10 m) on 0.2 m cells.
  const double tolerance = 1e-11;
  for (std::size_t e = 0; e < hexahedra.size(); ++e) {
    EXPECT_LT((hexahedra.rotations()[e] - expected.rotations[e]).norm(), tolerance) << e;
  }
  EXPECT_LT((flatten(f) - expected.force).norm(), tolerance * expected.force.norm());
  EXPECT_LT((flatten(df) - expected.dForce).norm(), tolerance * expected.dForce.norm());
  EXPECT_LT((K - expected.K).norm(), tolerance * expected.K.norm());
  EXPECT_NEAR(hexahedra.energy(method, x), expected.energy, tolerance * expected.energy);
  // Elements with their own entry: the same numbers as the kernel (element 0, element 7).
  for (std::size_t e : {std::size_t{0}, std::size_t{7}}) {
    EXPECT_EQ(hexahedra.constant(e).stiffness, expected.constants[e].stiffness) << e;
  }

  // At rest (rigidly moved), shared constants still give zero force to round-off.
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(1.1, Vec3d(0, 1, 1).normalized()).toRotationMatrix();
  std::vector<Vec3d> rigid;
  for (const Vec3d& p : grid.mesh.points) rigid.push_back(Q * p + Vec3d(1, 2, 3));
  std::vector<Vec3d> restForce(x.size(), Vec3d::Zero());
  hexahedra.addForce(method, rigid, restForce, pool);
  if (method != fem::RotationMethod::small) {
    EXPECT_LT(flatten(restForce).norm(), 1e-10 * expected.force.norm());
  }
}

INSTANTIATE_TEST_SUITE_P(CorotationalElements, SharedHexahedra,
                         ::testing::Values(fem::RotationMethod::small, fem::RotationMethod::large,
                                           fem::RotationMethod::polar, fem::RotationMethod::svd),
                         [](const auto& info) {
                           return std::string(fem::rotationMethodName(info.param));
                         });

TEST(CorotationalElements, RemovedHexahedraKeepTheirSharedConstants) {
  const ThreadPool pool(1);
  const Grid grid;
  Hexahedra hexahedra = makeHexahedra(grid, pool);
  const std::vector<Index> removed{1, 7, 12};
  hexahedra.removeElements(removed);

  // The same elements read afresh.
  std::vector<Hexahedra::Indices> kept = grid.elements();
  std::vector<double> youngModulus = grid.youngModulus;
  applyRemoval(kept, removed);
  applyRemoval(youngModulus, removed);
  Hexahedra fresh;
  fresh.setElements(kept, grid.mesh.points.size());
  fresh.computeConstants(grid.mesh.points, youngModulus, kPoissonRatio, pool);
  EXPECT_EQ(fresh.distinctConstantCount(), 2u);  // element 7, the other modulus, is gone

  const std::vector<Vec3d> x = deformed(grid.mesh.points);
  std::vector<Vec3d> f(x.size(), Vec3d::Zero()), expected(x.size(), Vec3d::Zero());
  hexahedra.addForce(fem::RotationMethod::large, x, f, pool);
  fresh.addForce(fem::RotationMethod::large, x, expected, pool);
  EXPECT_LT((flatten(f) - flatten(expected)).norm(), 1e-11 * flatten(expected).norm());
}

using Tetrahedra = CorotationalElements<fem::CorotationalTetrahedron>;

Tetrahedra makeTetrahedra(const Grid& grid, const ThreadPool& pool) {
  Tetrahedra tetrahedra;
  const std::vector<Tetrahedra::Indices> elements(grid.mesh.tetrahedra.begin(),
                                                  grid.mesh.tetrahedra.end());
  tetrahedra.setElements(elements, grid.mesh.points.size());
  std::vector<double> youngModulus(elements.size(), 3000.0);
  youngModulus[7] = 5000.0;
  tetrahedra.computeConstants(grid.mesh.points, youngModulus, kPoissonRatio, pool);
  return tetrahedra;
}

/// df of three products at the positions of one addForce, each from zero.
std::vector<std::vector<Vec3d>> threeProducts(Tetrahedra& tetrahedra, const std::vector<Vec3d>& x,
                                              const std::vector<std::vector<Vec3d>>& dx,
                                              const ThreadPool& pool) {
  std::vector<Vec3d> f(x.size(), Vec3d::Zero());
  tetrahedra.addForce(fem::RotationMethod::large, x, f, pool);
  std::vector<std::vector<Vec3d>> df;
  for (const std::vector<Vec3d>& d : dx) {
    df.emplace_back(x.size(), Vec3d::Zero());
    tetrahedra.addDForce(d, df.back(), -0.3, pool);
  }
  return df;
}

TEST(CorotationalElements, TetrahedronProductsAtOnePointAgreeWithTheElementLoop) {
  const Grid grid;
  const std::vector<Vec3d> x = deformed(grid.mesh.points);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<std::vector<Vec3d>> dx(3, std::vector<Vec3d>(x.size()));
  for (auto& d : dx)
    for (Vec3d& v : d) v = Vec3d(unit(rng), unit(rng), unit(rng));
  const ThreadPool one(1), two(2);
  Tetrahedra tetrahedra = makeTetrahedra(grid, one);
  const auto df = threeProducts(tetrahedra, x, dx, one);
  // The element loop on each dx: the first product at a point of a fresh model.
  for (std::size_t k = 0; k < dx.size(); ++k) {
    Tetrahedra fresh = makeTetrahedra(grid, one);
    const auto expected = threeProducts(fresh, x, {dx[k]}, one)[0];
    EXPECT_LT((flatten(df[k]) - flatten(expected)).norm(), 1e-13 * flatten(expected).norm())
        << "product " << k;
  }
  // Later points: the blocks from the first product on, refilled at each point.
  const auto again = threeProducts(tetrahedra, deformed(x), dx, one);
  Tetrahedra fresh = makeTetrahedra(grid, one);
  const auto expected = threeProducts(fresh, deformed(x), {dx[0]}, one)[0];
  EXPECT_LT((flatten(again[0]) - flatten(expected)).norm(), 1e-13 * flatten(expected).norm());
  // The same numbers on two threads.
  Tetrahedra parallel = makeTetrahedra(grid, two);
  EXPECT_EQ(threeProducts(parallel, x, dx, two), df);
}

}  // namespace
}  // namespace stroma::test
