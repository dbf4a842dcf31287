// SPDX-License-Identifier: MIT
// Grid transfers of the multigrid (GridTransfer.h): the trilinear prolongation reproduces linear
// fields exactly on sparse grids with holes and odd sizes, bad meshes are refused, and the
// Galerkin operator P^T K P of a linear hexahedral grid equals the stiffness assembled directly
// on the coarse grid (the nesting of seed 001 ch. 4 sec. 3).
#include "GridTransfer.h"

#include <gtest/gtest.h>

#include <map>

#include "MultigridScenes.h"
#include "SparseGrid.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

using multigrid::Prolongation;

// A box of 7 x 5 x 3 cells with holes (every cell with (i + 2j + 3k) % 4 == 0 dropped).
sparsegrid::SparseGrid holedGrid() {
  sparsegrid::SparseGrid grid;
  grid.box.cells = {7, 5, 3};
  grid.box.origin = Vec3d(-1, 0.5, 2);
  grid.box.spacing = Vec3d(0.3, 0.2, 0.5);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 7; ++i)
        if ((i + 2 * j + 3 * k) % 4 != 0) grid.cells.push_back(grid.box.cellIndex(i, j, k));
  grid.types.assign(grid.cells.size(), sparsegrid::CellType::full);
  grid.fractions.assign(grid.cells.size(), 1.0);
  sparsegrid::makeGridElements(grid);
  return grid;
}

Vec3d linearField(const Vec3d& p) {
  Eigen::Matrix3d B;
  B << 1.5, -0.3, 2.0, 0.7, 0.1, -1.1, -0.4, 0.9, 0.25;
  return Vec3d(0.2, -3.0, 1.0) + B * p;
}

TEST(GridTransfer, ProlongationReproducesLinearFieldsOnEveryLevel) {
  const sparsegrid::SparseGrid made = holedGrid();
  sparsegrid::SparseGrid fine;
  std::string error;
  ASSERT_TRUE(multigrid::makeLatticeGrid(made.points, made.hexahedra, nullptr, fine, error))
      << error;
  int levels = 0;
  while (fine.cells.size() > 1) {
    std::vector<std::array<Index, 8>> children;
    const sparsegrid::SparseGrid coarse = sparsegrid::coarsenSparseGrid(fine, &children);
    const Prolongation P = multigrid::makeProlongation(fine, coarse, children);
    ASSERT_EQ(P.rows(), Eigen::Index(fine.points.size()));
    ASSERT_EQ(P.cols(), Eigen::Index(coarse.points.size()));
    Eigen::MatrixXd coarseField(coarse.points.size(), 3);
    for (std::size_t i = 0; i < coarse.points.size(); ++i)
      coarseField.row(Eigen::Index(i)) = linearField(coarse.points[i]).transpose();
    const Eigen::MatrixXd interpolated = P * coarseField;
    double worst = 0;
    for (std::size_t i = 0; i < fine.points.size(); ++i)
      worst = std::max(worst,
                       (interpolated.row(Eigen::Index(i)).transpose() - linearField(fine.points[i]))
                           .lpNorm<Eigen::Infinity>());
    EXPECT_LT(worst, 1e-12) << "level " << levels;
    // Every fine point has at most 8 weights, all positive.
    for (Eigen::Index i = 0; i < P.outerSize(); ++i) {
      int count = 0;
      for (Prolongation::InnerIterator e(P, i); e; ++e, ++count) EXPECT_GT(e.value(), 0);
      EXPECT_GE(count, 1);
      EXPECT_LE(count, 8);
    }
    fine = coarse;
    ++levels;
  }
  EXPECT_EQ(levels, 3);  // 7 -> 4 -> 2 -> 1 cells along x
}

TEST(GridTransfer, ExpandedProlongationZeroesFixedRows) {
  const sparsegrid::SparseGrid fine = holedGrid();
  std::vector<std::array<Index, 8>> children;
  const sparsegrid::SparseGrid coarse = sparsegrid::coarsenSparseGrid(fine, &children);
  const Prolongation P = multigrid::makeProlongation(fine, coarse, children);
  std::vector<char> fixed(3 * fine.points.size(), 0);
  fixed[4] = fixed[5] = 1;  // point 1, components y and z
  const Eigen::SparseMatrix<double> P3 = multigrid::expandProlongation(P, 3, fixed);
  ASSERT_EQ(P3.rows(), 3 * P.rows());
  ASSERT_EQ(P3.cols(), 3 * P.cols());
  const Eigen::MatrixXd dense = P3, scalar = P;
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    for (Eigen::Index j = 0; j < P.cols(); ++j)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          const bool zeroed = fixed[std::size_t(3 * i + a)] != 0;
          const double expected = a == b && !zeroed ? scalar(i, j) : 0.0;
          ASSERT_EQ(dense(3 * i + a, 3 * j + b), expected);
        }
}

TEST(GridTransfer, RefusesMeshesThatAreNotLatticeCells) {
  const sparsegrid::SparseGrid made = holedGrid();
  sparsegrid::SparseGrid grid;
  std::string error;
  // A corner moved off its lattice point.
  std::vector<Vec3d> moved = made.points;
  moved[made.hexahedra[3][6]] += Vec3d(0.01, 0, 0);
  EXPECT_FALSE(multigrid::makeLatticeGrid(moved, made.hexahedra, nullptr, grid, error));
  EXPECT_NE(error.find("not a cell of the axis-aligned lattice"), std::string::npos) << error;
  // Corners in another order.
  std::vector<Hexahedron> reordered = made.hexahedra;
  std::swap(reordered[2][1], reordered[2][3]);
  EXPECT_FALSE(multigrid::makeLatticeGrid(made.points, reordered, nullptr, grid, error));
  // A repeated cell, an index out of range, no hexahedra.
  std::vector<Hexahedron> repeated = made.hexahedra;
  repeated.push_back(repeated[5]);
  EXPECT_FALSE(multigrid::makeLatticeGrid(made.points, repeated, nullptr, grid, error));
  EXPECT_NE(error.find("repeats"), std::string::npos) << error;
  std::vector<Hexahedron> outOfRange = made.hexahedra;
  outOfRange[0][7] = Index(made.points.size());
  EXPECT_FALSE(multigrid::makeLatticeGrid(made.points, outOfRange, nullptr, grid, error));
  EXPECT_FALSE(multigrid::makeLatticeGrid(made.points, {}, nullptr, grid, error));
}

/// K = df/dx of a loaded scene with kFactor 1 (no constraint in these scenes).
Eigen::SparseMatrix<double> stiffness(LoadedScene& s) {
  MechanicalOperations mop(s.body(), s.scene->timing());
  const VecId f = mop.allocDeriv();
  mop.computeForce(MechanicalParams{}, f);
  MechanicalParams mp;
  mp.mFactor = 0;
  mp.kFactor = 1;
  AssembledMatrix A;
  mop.assemble(mp, A);
  return A.matrix();
}

std::string gridScene(int nx, int ny, int nz) {
  return "<Node name=\"root\" gravity=\"0 0 0\">\n<Node name=\"Body\">\n"
         "<RegularGridTopology name=\"grid\" n=\"" +
         std::to_string(nx + 1) + " " + std::to_string(ny + 1) + " " + std::to_string(nz + 1) +
         "\" min=\"0 0 0\" max=\"2 1 1.5\"/>\n"
         "<MechanicalObject name=\"dofs\" position=\"@grid.position\"/>\n"
         "<HexahedronFEMForceField method=\"small\" youngModulus=\"40000\" "
         "poissonRatio=\"0.3\"/>\n</Node>\n</Node>\n";
}

TEST(GridTransfer, GalerkinOperatorEqualsTheCoarseGridStiffness) {
  LoadedScene fineScene(gridScene(4, 2, 6)), coarseScene(gridScene(2, 1, 3));
  ASSERT_TRUE(fineScene.loaded) << fineScene.log();
  ASSERT_TRUE(coarseScene.loaded) << coarseScene.log();
  const Eigen::SparseMatrix<double> Kf = stiffness(fineScene), Kc = stiffness(coarseScene);

  const Topology* topology = fineScene.body().get<Topology>();
  ASSERT_NE(topology, nullptr);
  sparsegrid::SparseGrid fine;
  std::string error;
  ASSERT_TRUE(multigrid::makeLatticeGrid(topology->positions(), topology->hexahedra(), nullptr,
                                         fine, error))
      << error;
  std::vector<std::array<Index, 8>> children;
  const sparsegrid::SparseGrid coarse = sparsegrid::coarsenSparseGrid(fine, &children);
  const Eigen::SparseMatrix<double> P =
      multigrid::expandProlongation(multigrid::makeProlongation(fine, coarse, children), 3, {});
  const Eigen::MatrixXd galerkin = Eigen::MatrixXd(P.transpose() * Kf * P);

  // The coarse grid's points in the coarse scene's numbering, found by position.
  const std::vector<Vec3d>& scenePoints = coarseScene.body().get<Topology>()->positions();
  ASSERT_EQ(scenePoints.size(), coarse.points.size());
  std::vector<Index> sceneIndex(coarse.points.size(), kInvalidIndex);
  for (std::size_t i = 0; i < coarse.points.size(); ++i)
    for (std::size_t j = 0; j < scenePoints.size(); ++j)
      if ((coarse.points[i] - scenePoints[j]).norm() < 1e-12) sceneIndex[i] = Index(j);
  const Eigen::MatrixXd direct = Kc;
  double worst = 0;
  for (std::size_t i = 0; i < coarse.points.size(); ++i)
    for (std::size_t j = 0; j < coarse.points.size(); ++j) {
      ASSERT_NE(sceneIndex[i], kInvalidIndex);
      worst = std::max(worst, (galerkin.block<3, 3>(3 * i, 3 * j) -
                               direct.block<3, 3>(3 * sceneIndex[i], 3 * sceneIndex[j]))
                                  .cwiseAbs()
                                  .maxCoeff());
    }
  EXPECT_LT(worst, 1e-10 * direct.cwiseAbs().maxCoeff());
  EXPECT_GT(direct.cwiseAbs().maxCoeff(), 1e3);  // a real stiffness was compared
}

}  // namespace
}  // namespace stroma::test
