// SPDX-License-Identifier: MIT
// Sparse grids from voxels (plugins/SparseGrid/src/ImageGrid.h): the filled volume equals the
// inside voxels' volume to round-off and each fraction equals the brute-force overlap of voxel
// boxes with the cell; a voxelized sphere against the analytic volume; cell types on a grid
// aligned with the voxels; two labels; a box larger than the image; virtual finer levels; no
// inside voxel is an error.
#include "ImageGrid.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "SparseGrid.h"

namespace stroma::sparsegrid {
namespace {

/// A cube image of n^3 voxels of size h with voxel (0,0,0) centred at `origin`, valued by `f` of
/// the voxel centre.
template <typename F>
image::VolumeImage makeImage(int n, double h, const Vec3d& origin, F f) {
  image::VolumeImage im;
  im.size = {n, n, n};
  im.spacing = Vec3d::Constant(h);
  im.origin = origin;
  im.values.resize(im.voxelCount());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) im.at(i, j, k) = f(im.voxelCenter(i, j, k));
  return im;
}

/// The grid box covering the image with `cells` cells per axis.
GridBox imageBox(const image::VolumeImage& im, int cells) {
  GridBox box;
  box.cells = {cells, cells, cells};
  box.origin = im.lowerCorner();
  box.spacing = (im.upperCorner() - im.lowerCorner()) / cells;
  return box;
}

VoxelSelection threshold(double value) {
  VoxelSelection s;
  s.threshold = value;
  return s;
}
VoxelSelection labels(std::vector<double> values) {
  VoxelSelection s;
  s.labels = std::move(values);
  return s;
}

double insideVolume(const image::VolumeImage& im, const std::vector<std::uint8_t>& inside) {
  double count = 0;
  for (std::uint8_t f : inside) count += f;
  return count * im.spacing.prod();
}

/// The filled fraction of one cell by brute force: every inside voxel's box clipped to the cell.
double bruteForceFraction(const image::VolumeImage& im, const std::vector<std::uint8_t>& inside,
                          const GridBox& box, std::uint64_t cell) {
  const auto c = box.cellCoordinates(cell);
  const Vec3d lo = box.origin + Vec3d(c[0], c[1], c[2]).cwiseProduct(box.spacing);
  const Vec3d hi = lo + box.spacing;
  double volume = 0;
  for (int k = 0; k < im.size[2]; ++k)
    for (int j = 0; j < im.size[1]; ++j)
      for (int i = 0; i < im.size[0]; ++i) {
        if (!inside[im.index(i, j, k)]) continue;
        const Vec3d vlo = im.voxelCenter(i, j, k) - im.spacing / 2, vhi = vlo + im.spacing;
        const Vec3d d = hi.cwiseMin(vhi) - lo.cwiseMax(vlo);
        if (d.minCoeff() > 0) volume += d.prod();
      }
  return volume / box.spacing.prod();
}

TEST(ImageGrid, VoxelizedSphereVolumeIsExactAndCloseToTheSphere) {
  const double r = 0.8;
  const image::VolumeImage im = makeImage(
      40, 0.05, Vec3d::Constant(-0.975), [&](const Vec3d& p) { return p.norm() <= r ? 1.0 : 0.0; });
  const std::vector<std::uint8_t> inside = selectVoxels(im, {});
  // 12 cells across 40 voxels: cell boundaries fall inside voxels.
  const GridBox box = imageBox(im, 12);
  SparseGrid grid;
  std::string error;
  ASSERT_TRUE(buildSparseGridFromVoxels(im, inside, box, grid, error)) << error;
  const double voxels = insideVolume(im, inside);
  EXPECT_NEAR(grid.filledVolume(), voxels, 1e-12 * voxels);
  const double sphere = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(voxels, sphere, 0.01 * sphere);  // the voxelization's own error
  // Every fraction is the brute-force overlap; full cells have only inside voxels.
  for (std::size_t e = 0; e < grid.cells.size(); ++e) {
    const double brute = bruteForceFraction(im, inside, box, grid.cells[e]);
    EXPECT_NEAR(grid.fractions[e], brute, 1e-12);
    if (grid.types[e] == CellType::full) {
      EXPECT_NEAR(brute, 1.0, 1e-12);
    } else {
      EXPECT_GT(brute, 0.0);
      EXPECT_LT(brute, 1.0 - 1e-12);
    }
  }
  // The cells dropped hold no inside voxel; a sphere of 0.8 in a box of 2 has both kinds.
  EXPECT_GT(grid.count(CellType::full), 0u);
  EXPECT_GT(grid.count(CellType::boundary), 0u);
  EXPECT_LT(grid.cells.size(), box.cellCount());
  // Boundary cells first, then full cells, each by increasing cell index (SOFA's order).
  const auto firstFull = grid.count(CellType::boundary);
  for (std::size_t e = 1; e < grid.cells.size(); ++e)
    if (e != firstFull) {
      EXPECT_LT(grid.cells[e - 1], grid.cells[e]);
    }
}

TEST(ImageGrid, GridAlignedWithTheVoxelsHasExactTypes) {
  // 16^3 voxels of 0.1; inside: the block of voxels 4 to 11 (aligned with cells of 2 voxels)
  // plus one voxel (0,0,0) alone in its cell.
  image::VolumeImage im = makeImage(16, 0.1, Vec3d::Zero(), [](const Vec3d& p) {
    return (p.array() > 0.35).all() && (p.array() < 1.15).all() ? 7.0 : 0.0;
  });
  im.at(0, 0, 0) = 7;
  const std::vector<std::uint8_t> inside = selectVoxels(im, threshold(7.0));
  SparseGrid grid;
  std::string error;
  ASSERT_TRUE(buildSparseGridFromVoxels(im, inside, imageBox(im, 8), grid, error)) << error;
  // The block fills 4^3 cells exactly; the lone voxel is one eighth of a boundary cell. No
  // rounding sliver marks a neighbouring cell.
  ASSERT_EQ(grid.cells.size(), 65u);
  EXPECT_EQ(grid.count(CellType::full), 64u);
  EXPECT_EQ(grid.count(CellType::boundary), 1u);
  EXPECT_EQ(grid.cells[0], 0u);
  EXPECT_NEAR(grid.fractions[0], 0.125, 1e-14);
  EXPECT_NEAR(grid.filledVolume(), 513 * 1e-3, 1e-14);
}

TEST(ImageGrid, TwoLabelsPartitionTheVolume) {
  // A two-tissue cylinder along z: label 1 inside radius 0.3, label 2 from 0.3 to 0.6.
  const image::VolumeImage im = makeImage(24, 0.05, Vec3d::Constant(-0.575), [](const Vec3d& p) {
    const double rho = std::hypot(p.x(), p.y());
    return rho <= 0.3 ? 1.0 : rho <= 0.6 ? 2.0 : 0.0;
  });
  const GridBox box = imageBox(im, 7);
  double volume[3];
  std::size_t cells[3];
  const std::vector<std::vector<double>> selections{{1}, {2}, {1, 2}};
  for (std::size_t s = 0; s < 3; ++s) {
    const auto inside = selectVoxels(im, labels(selections[s]));
    SparseGrid grid;
    std::string error;
    ASSERT_TRUE(buildSparseGridFromVoxels(im, inside, box, grid, error)) << error;
    volume[s] = grid.filledVolume();
    cells[s] = grid.cells.size();
    EXPECT_NEAR(volume[s], insideVolume(im, inside), 1e-12);
  }
  EXPECT_NEAR(volume[0] + volume[1], volume[2], 1e-12);
  EXPECT_LT(cells[0], cells[2]);
  // Label 2 only: the core is a hole, so no cell of the outer tissue's grid is full there.
  EXPECT_NEAR(volume[0], std::numbers::pi * 0.09 * 1.2, 0.05 * std::numbers::pi * 0.09 * 1.2);
}

TEST(ImageGrid, BoxLargerThanTheImage) {
  // All voxels inside; the grid's box overhangs the image by half a cell on each side.
  const image::VolumeImage im =
      makeImage(4, 0.25, Vec3d::Constant(0.125), [](const Vec3d&) { return 1.0; });
  GridBox box;
  box.cells = {3, 3, 3};
  box.spacing = Vec3d::Constant(0.5);
  box.origin = Vec3d::Constant(-0.25);
  const auto inside = selectVoxels(im, {});
  SparseGrid grid;
  std::string error;
  ASSERT_TRUE(buildSparseGridFromVoxels(im, inside, box, grid, error)) << error;
  // Every cell overlaps the image [0, 1]^3; the centre one lies inside it, the others overhang.
  ASSERT_EQ(grid.cells.size(), 27u);
  EXPECT_EQ(grid.count(CellType::full), 1u);
  EXPECT_NEAR(grid.filledVolume(), 1.0, 1e-14);
  EXPECT_NEAR(grid.fractions[0], 0.125, 1e-14);  // a corner cell: half along each axis
}

TEST(ImageGrid, VirtualFinerLevelsKeepTheVolume) {
  const image::VolumeImage im = makeImage(
      32, 1.0 / 32, Vec3d::Constant(1.0 / 64),
      [](const Vec3d& p) { return (p - Vec3d(0.5, 0.5, 0.5)).norm() < 0.37 ? 3.0 : 1.0; });
  const auto inside = selectVoxels(im, threshold(2.0));
  SparseGrid fine;
  std::string error;
  ASSERT_TRUE(buildSparseGridFromVoxels(im, inside, imageBox(im, 20), fine, error)) << error;
  const SparseGrid coarse = coarsenSparseGrid(fine);
  EXPECT_NEAR(coarse.filledVolume(), fine.filledVolume(), 1e-12);
  EXPECT_NEAR(fine.filledVolume(), insideVolume(im, inside), 1e-12);
  EXPECT_EQ(coarse.box.cells, (std::array<int, 3>{10, 10, 10}));
}

TEST(ImageGrid, NoInsideVoxelIsAnError) {
  const image::VolumeImage im = makeImage(4, 1.0, Vec3d::Zero(), [](const Vec3d&) { return 1.0; });
  const VoxelSelection selection = threshold(2.0);
  SparseGrid grid;
  std::string error;
  EXPECT_FALSE(
      buildSparseGridFromVoxels(im, selectVoxels(im, selection), imageBox(im, 2), grid, error));
  EXPECT_NE(error.find("no inside voxel"), std::string::npos) << error;
  EXPECT_EQ(selection.describe(), "voxel >= 2 (threshold)");
  EXPECT_EQ(labels({1, 4}).describe(), "voxel with a label among 1 4");
}

TEST(ImageGrid, BuildsHundredThousandCellsQuickly) {
  // 128^3 voxels (2.1e6) into 47^3 = 103823 cells. Timing printed, not asserted.
  const image::VolumeImage im = makeImage(
      128, 1.0 / 128, Vec3d::Constant(1.0 / 256),
      [](const Vec3d& p) { return (p - Vec3d(0.5, 0.5, 0.5)).norm() < 0.45 ? 1.0 : 0.0; });
  const auto inside = selectVoxels(im, {});
  const auto start = std::chrono::steady_clock::now();
  SparseGrid grid;
  std::string error;
  ASSERT_TRUE(buildSparseGridFromVoxels(im, inside, imageBox(im, 47), grid, error)) << error;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ info ] 128^3 voxels into 47^3 cells (%zu kept) in %.3f s\n", grid.cells.size(),
              seconds);
  EXPECT_NEAR(grid.filledVolume(), insideVolume(im, inside), 1e-11);
}

}  // namespace
}  // namespace stroma::sparsegrid
