// SPDX-License-Identifier: MIT
// The sparse-grid kernels (plugins/SparseGrid/src/SparseGrid.h, TriangleBoxOverlap.h): the
// triangle/box test, the classification of the cells of a box and of a sphere against their
// geometry, the measured volume converging to the exact one, the mesh made of the kept cells,
// orientation-free and hole-tolerant flood fill, coarser levels, and the time to build 10^5 cells.
#include "SparseGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <set>
#include <tuple>

#include "SurfaceMeshes.h"
#include "TriangleBoxOverlap.h"
#include "topology/MeshGeometry.h"

namespace stroma::test {
namespace {

using sparsegrid::CellType;
using sparsegrid::GridBox;
using sparsegrid::SparseGrid;

SparseGrid build(const TriangleSurface& s, const GridBox& box, int samples = 4) {
  SparseGrid grid;
  std::string error;
  EXPECT_TRUE(sparsegrid::buildSparseGrid({s.points, s.triangles}, box, samples, grid, error))
      << error;
  return grid;
}

/// A box of `cells` cubic cells per axis around [lo, hi], grown by 1 % of the side (as the
/// component does when the scene gives no box).
GridBox boxAround(const Vec3d& lo, const Vec3d& hi, int cells) {
  const double side = (hi - lo).maxCoeff();
  GridBox box;
  box.cells = {cells, cells, cells};
  box.origin = lo - Vec3d::Constant(0.01 * side);
  box.spacing = (hi - lo + Vec3d::Constant(0.02 * side)) / cells;
  return box;
}

/// Distance from `p` to the nearest and farthest points of cell `cell`.
std::pair<double, double> distanceRange(const GridBox& box, std::uint64_t cell, const Vec3d& p) {
  const auto c = box.cellCoordinates(cell);
  const Vec3d lo = box.origin + Vec3d(c[0], c[1], c[2]).cwiseProduct(box.spacing);
  const Vec3d hi = lo + box.spacing;
  const Vec3d nearest = p.cwiseMax(lo).cwiseMin(hi);
  Vec3d farthest;
  for (int a = 0; a < 3; ++a)
    farthest[a] = std::abs(p[a] - lo[a]) > std::abs(p[a] - hi[a]) ? lo[a] : hi[a];
  return {(nearest - p).norm(), (farthest - p).norm()};
}

// --- Triangle / box overlap ----------------------------------------------------------------------

TEST(TriangleBoxOverlap, SeparatingAxes) {
  using sparsegrid::triangleOverlapsBox;
  const Vec3d c = Vec3d::Zero(), h = Vec3d::Constant(0.5);
  // Inside, and crossing the box.
  EXPECT_TRUE(triangleOverlapsBox(c, h, {-0.1, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}));
  EXPECT_TRUE(triangleOverlapsBox(c, h, {-5, -5, 0}, {5, -5, 0}, {0, 5, 0}));
  // Touching a face counts.
  EXPECT_TRUE(triangleOverlapsBox(c, h, {0.5, -1, -1}, {0.5, 1, -1}, {0.5, 0, 1}));
  // Separated by a box face.
  EXPECT_FALSE(triangleOverlapsBox(c, h, {0.6, -1, -1}, {0.6, 1, -1}, {0.6, 0, 1}));
  // Separated by the triangle's plane only: a plane x + y + z = 1.6 passing near the corner.
  EXPECT_FALSE(triangleOverlapsBox(c, h, {1.6, 0, 0}, {0, 1.6, 0}, {0, 0, 1.6}));
  EXPECT_TRUE(triangleOverlapsBox(c, h, {1.4, 0, 0}, {0, 1.4, 0}, {0, 0, 1.4}));
  // Separated by an edge cross product only: a thin triangle passing by an edge of the box, its
  // bounding box and plane overlapping the box.
  EXPECT_FALSE(triangleOverlapsBox(c, h, {1.1, 0, -1}, {0, 1.1, -1}, {0, 1.1, 1}));
  EXPECT_TRUE(triangleOverlapsBox(c, h, {0.9, 0, -1}, {0, 0.9, -1}, {0, 0.9, 1}));
  // A degenerate triangle (a segment) through the box, and one beside it.
  EXPECT_TRUE(triangleOverlapsBox(c, h, {-1, 0, 0}, {1, 0, 0}, {1, 0, 0}));
  EXPECT_FALSE(triangleOverlapsBox(c, h, {-1, 0.7, 0}, {1, 0.7, 0}, {1, 0.7, 0}));
}

// --- A box surface: counts and fractions known exactly
// ---------------------------------------------

TEST(SparseGrid, BoxSurfaceCellsMatchTheGeometry) {
  // The box [0.15, 0.85]^3 in 10 x 10 x 10 cells of 0.1: its faces cross cells 1 and 8 in their
  // middle. Boundary: cells with indices in [1, 8] and one of them 1 or 8 (8^3 - 6^3); full:
  // indices in [2, 7] (6^3); the 488 others empty.
  const TriangleSurface cube = boxSurface(Vec3d::Constant(0.15), Vec3d::Constant(0.85));
  GridBox box;
  box.cells = {10, 10, 10};
  box.spacing = Vec3d::Constant(0.1);
  const SparseGrid grid = build(cube, box);
  EXPECT_EQ(grid.count(CellType::boundary), 296u);
  EXPECT_EQ(grid.count(CellType::full), 216u);
  EXPECT_EQ(grid.cells.size(), 512u);
  // Face cells are half full, edge cells a quarter, corner cells an eighth. The faces lie on
  // sub-cell planes (4 samples of 0.025): the sub-cells on both sides are surface ones, and
  // those surrounded by them along edges and corners count a half (2 of 64 sub-cells off).
  for (std::size_t e = 0; e < grid.cells.size(); ++e) {
    const auto c = box.cellCoordinates(grid.cells[e]);
    int onFace = 0;
    for (int a = 0; a < 3; ++a) onFace += c[a] == 1 || c[a] == 8;
    EXPECT_NEAR(grid.fractions[e], std::ldexp(1.0, -onFace), 2.0 / 64 + 1e-12) << e;
  }
  EXPECT_NEAR(grid.filledVolume(), cube.volume(), 0.01 * cube.volume());
}

TEST(SparseGrid, UnalignedBoxVolumeWithinTheSubCellError) {
  // Faces at 0.1337 and 0.8661 cut the sub-cells (0.025 wide), whose 3 x 3 x 3 sample points
  // find a plane parallel to them within a sixth of their width: the error is at most
  // area x 0.025 / 6 = 3.3 % of the volume here, and the random offsets of the points in each
  // sub-cell make it cancel (measured 0.001 %).
  const TriangleSurface cube = boxSurface(Vec3d::Constant(0.1337), Vec3d::Constant(0.8661));
  GridBox box;
  box.cells = {10, 10, 10};
  box.spacing = Vec3d::Constant(0.1);
  const SparseGrid grid = build(cube, box);
  EXPECT_EQ(grid.count(CellType::boundary), 296u);
  EXPECT_EQ(grid.count(CellType::full), 216u);
  const double error = std::abs(grid.filledVolume() / cube.volume() - 1);
  std::printf("[ box      ] unaligned box: volume error %.3f %%\n", 100 * error);
  EXPECT_LT(error, 0.033);
}

// --- A sphere: classification against the geometry, volume convergence
// ----------------------------

TEST(SparseGrid, SphereCellsMatchTheGeometryAndVolumeConverges) {
  // Icosphere of radius 1 (5120 triangles): its points are on the unit sphere, its faces at
  // least at the inradius r_in from the centre. Full cells lie inside the unit sphere, boundary
  // cells reach between r_in and 1, empty cells miss the ball of radius r_in.
  const TriangleSurface sphere = icosphere(4);
  double rIn = 1;
  for (const Triangle& t : sphere.triangles) {
    const Vec3d& a = sphere.points[t[0]];
    const Vec3d n = (sphere.points[t[1]] - a).cross(sphere.points[t[2]] - a).normalized();
    rIn = std::min(rIn, std::abs(n.dot(a)));
  }
  const double exact = sphere.volume();  // of the polyhedron the grid is built on
  // Volume error tolerated per cell count across (measured with 4 samples per axis: 8 0.07 %,
  // 16 0.014 %, 32 0.006 %, 64 0.0008 %), against the polyhedron's exact volume.
  const std::pair<int, double> cases[] = {{8, 2e-3}, {16, 1e-3}, {32, 5e-4}, {64, 2e-4}};
  for (const auto& [cells, tolerance] : cases) {
    SCOPED_TRACE(cells);
    const GridBox box = boxAround(Vec3d::Constant(-1), Vec3d::Constant(1), cells);
    const SparseGrid grid = build(sphere, box);
    std::vector<std::size_t> keptAs(box.cellCount(), SIZE_MAX);
    for (std::size_t e = 0; e < grid.cells.size(); ++e) keptAs[grid.cells[e]] = e;
    for (std::uint64_t cell = 0; cell < box.cellCount(); ++cell) {
      const auto [nearest, farthest] = distanceRange(box, cell, Vec3d::Zero());
      const std::size_t e = keptAs[cell];
      if (e == SIZE_MAX) {
        EXPECT_GT(nearest, rIn) << "empty cell " << cell << " reaches inside the surface";
        continue;
      }
      if (grid.types[e] == CellType::full) {
        EXPECT_LT(farthest, 1.0) << "full cell " << cell << " reaches outside the surface";
        EXPECT_EQ(grid.fractions[e], 1.0);
      } else {
        EXPECT_LE(nearest, 1.0) << "boundary cell " << cell << " entirely outside";
        EXPECT_GE(farthest, rIn) << "boundary cell " << cell << " entirely inside";
        EXPECT_GE(grid.fractions[e], 0.0);
        EXPECT_LE(grid.fractions[e], 1.0);
      }
    }
    const double error = std::abs(grid.filledVolume() / exact - 1);
    std::printf("[ sphere   ] %2d cells across: %6zu full, %6zu boundary, volume error %.4f %%\n",
                cells, grid.count(CellType::full), grid.count(CellType::boundary), 100 * error);
    EXPECT_LT(error, tolerance);
    // Counting boundary cells as full or as empty brackets the volume.
    const double cellVolume = box.spacing.prod();
    EXPECT_LT(grid.count(CellType::full) * cellVolume, exact);
    EXPECT_GT(grid.cells.size() * cellVolume, exact);
  }
}

// --- The mesh of the kept cells ----------------------------------------------------------------

TEST(SparseGrid, PointsAreSharedAndHexahedraPositive) {
  const TriangleSurface sphere = icosphere(3, Vec3d(0.3, -0.2, 0.1), 0.7);
  GridBox box = boxAround(Vec3d(-0.4, -0.9, -0.6), Vec3d(1.0, 0.5, 0.8), 12);
  box.spacing.y() *= 1.3;  // non-cubic cells
  box.cells[2] = 9;
  box.spacing.z() *= 12.0 / 9;
  const SparseGrid grid = build(sphere, box);
  ASSERT_FALSE(grid.hexahedra.empty());
  // Each point once, and used.
  std::set<std::array<double, 3>> distinct;
  for (const Vec3d& p : grid.points) distinct.insert({p.x(), p.y(), p.z()});
  EXPECT_EQ(distinct.size(), grid.points.size());
  std::vector<int> uses(grid.points.size(), 0);
  for (std::size_t e = 0; e < grid.hexahedra.size(); ++e) {
    const Hexahedron& h = grid.hexahedra[e];
    for (Index v : h) ++uses[v];
    // The corners of the cell, in the order of TopologyTypes.h, and a positive volume.
    const auto c = box.cellCoordinates(grid.cells[e]);
    const Vec3d lo = box.origin + Vec3d(c[0], c[1], c[2]).cwiseProduct(box.spacing);
    const int corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int q = 0; q < 8; ++q)
      EXPECT_LT((grid.points[h[q]] - lo -
                 Vec3d(corners[q][0], corners[q][1], corners[q][2]).cwiseProduct(box.spacing))
                    .norm(),
                1e-12);
    EXPECT_NEAR(signedVolume(grid.points, h), box.spacing.prod(), 1e-12);
  }
  for (int u : uses) EXPECT_GT(u, 0);
  // SOFA's numbering: points by increasing (x, y, z), boundary cells before full ones.
  for (std::size_t p = 1; p < grid.points.size(); ++p) {
    const Vec3d &a = grid.points[p - 1], &b = grid.points[p];
    EXPECT_TRUE(std::tie(a.x(), a.y(), a.z()) < std::tie(b.x(), b.y(), b.z())) << p;
  }
  EXPECT_TRUE(std::is_partitioned(grid.types.begin(), grid.types.end(),
                                  [](CellType t) { return t == CellType::boundary; }));
  EXPECT_TRUE(
      std::is_sorted(grid.cells.begin(), grid.cells.begin() + grid.count(CellType::boundary)));
  EXPECT_TRUE(
      std::is_sorted(grid.cells.begin() + grid.count(CellType::boundary), grid.cells.end()));
  // Neighbouring cells share their 4 face points: points = distinct corners of the cells.
  std::set<std::uint64_t> corners;
  for (std::uint64_t cell : grid.cells) {
    const auto c = box.cellCoordinates(cell);
    for (int q = 0; q < 8; ++q)
      corners.insert((c[0] + (q & 1)) + 100 * ((c[1] + (q >> 1 & 1)) + 100 * (c[2] + (q >> 2))));
  }
  EXPECT_EQ(corners.size(), grid.points.size());
}

// --- Orientation, non-manifold surfaces, holes ---------------------------------------------------

TEST(SparseGrid, InsideOutSurfaceGivesTheSameGrid) {
  const TriangleSurface sphere = icosphere(3);
  const GridBox box = boxAround(Vec3d::Constant(-1), Vec3d::Constant(1), 14);
  const SparseGrid a = build(sphere, box), b = build(sphere.flipped(), box);
  EXPECT_EQ(a.cells, b.cells);
  EXPECT_EQ(a.types, b.types);
  EXPECT_EQ(a.fractions, b.fractions);
}

TEST(SparseGrid, OverlappingAndWalledSurfacesFillTheirUnion) {
  // Two overlapping boxes (a non-manifold, self-intersecting surface) fill their union; a wall
  // inside a box (a triangle pair shared by nothing else) changes no cell type.
  TriangleSurface two = boxSurface(Vec3d::Constant(0.1337), Vec3d(0.5713, 0.5713, 0.8661));
  const TriangleSurface second = boxSurface(Vec3d(0.4291, 0.4291, 0.1337), Vec3d::Constant(0.8661));
  for (Triangle t : second.triangles) {
    for (Index& v : t) v += Index(two.points.size());
    two.triangles.push_back(t);
  }
  two.points.insert(two.points.end(), second.points.begin(), second.points.end());
  GridBox box;
  box.cells = {10, 10, 10};
  box.spacing = Vec3d::Constant(0.1);
  const SparseGrid grid = build(two, box);
  const double a = 0.5713 - 0.1337, overlap = 0.5713 - 0.4291, height = 0.8661 - 0.1337;
  const double unionVolume = (2 * a * a - overlap * overlap) * height;
  const double error = std::abs(grid.filledVolume() / unionVolume - 1);
  std::printf("[ union    ] two overlapping boxes: volume error %.3f %%\n", 100 * error);
  EXPECT_LT(error, 0.033);  // the bound of UnalignedBoxVolumeWithinTheSubCellError

  TriangleSurface walled = boxSurface(Vec3d::Constant(0.13), Vec3d::Constant(0.87));
  const Index base = Index(walled.points.size());
  for (const Vec3d& p : {Vec3d(0.13, 0.13, 0.51), Vec3d(0.87, 0.13, 0.51), Vec3d(0.87, 0.87, 0.51),
                         Vec3d(0.13, 0.87, 0.51)})
    walled.points.push_back(p);
  walled.triangles.push_back({base, base + 1, base + 2});
  walled.triangles.push_back({base, base + 2, base + 3});
  const SparseGrid plain = build(boxSurface(Vec3d::Constant(0.13), Vec3d::Constant(0.87)), box);
  const SparseGrid withWall = build(walled, box);
  auto sorted = [](std::vector<std::uint64_t> cells) {
    std::sort(cells.begin(), cells.end());
    return cells;
  };
  EXPECT_EQ(sorted(withWall.cells), sorted(plain.cells));
  // The wall's cells become boundary cells, still filled (but where the wall meets the faces,
  // the surface sub-cells lose an inside neighbour).
  EXPECT_EQ(withWall.count(CellType::boundary), plain.count(CellType::boundary) + 36);
  EXPECT_NEAR(withWall.filledVolume(), plain.filledVolume(), 0.005 * plain.filledVolume());
}

TEST(SparseGrid, HolesNarrowerThanACellAreClosedWiderOnesLetTheFloodIn) {
  const TriangleSurface sphere = icosphere(4);  // triangles about 0.08 wide
  TriangleSurface holed = sphere;
  holed.triangles.erase(holed.triangles.begin());  // one triangle missing
  const GridBox box = boxAround(Vec3d::Constant(-1), Vec3d::Constant(1), 10);  // cells of 0.2
  const SparseGrid closed = build(sphere, box), small = build(holed, box);
  EXPECT_EQ(small.cells, closed.cells);
  EXPECT_EQ(small.types, closed.types);
  EXPECT_NEAR(small.filledVolume(), closed.filledVolume(), 0.02 * closed.filledVolume());

  // A box open on top (a hole as wide as the box): the flood fills it, nothing is full, and
  // almost nothing is filled (sample points of sub-cells surrounded by the surface, where two
  // walls meet: 0.4 % of the box's volume).
  TriangleSurface open = boxSurface(Vec3d::Constant(0.13), Vec3d::Constant(0.87));
  open.triangles.erase(open.triangles.begin() + 2, open.triangles.begin() + 4);  // z = hi face
  GridBox cells10;
  cells10.cells = {10, 10, 10};
  cells10.spacing = Vec3d::Constant(0.1);
  const SparseGrid openGrid = build(open, cells10);
  EXPECT_EQ(openGrid.count(CellType::full), 0u);
  EXPECT_LT(openGrid.filledVolume(), 0.01 * 0.74 * 0.74 * 0.74);
  EXPECT_GT(openGrid.count(CellType::boundary), 0u);
}

// --- Coarser levels ------------------------------------------------------------------------------

TEST(SparseGrid, CoarserLevelGroupsChildren) {
  const TriangleSurface sphere = icosphere(3);
  const GridBox box = boxAround(Vec3d::Constant(-1), Vec3d::Constant(1), 15);  // odd: grows
  const SparseGrid fine = build(sphere, box);
  std::vector<std::array<Index, 8>> children;
  const SparseGrid coarse = sparsegrid::coarsenSparseGrid(fine, &children);
  EXPECT_EQ(coarse.box.cells, (std::array<int, 3>{8, 8, 8}));
  ASSERT_EQ(children.size(), coarse.cells.size());
  // Every fine cell is the child of exactly one coarse cell, at its corner.
  std::vector<int> parentCount(fine.cells.size(), 0);
  for (std::size_t c = 0; c < coarse.cells.size(); ++c) {
    int full = 0;
    double fraction = 0;
    for (int q = 0; q < 8; ++q) {
      const Index f = children[c][q];
      if (f == kInvalidIndex) continue;
      ++parentCount[f];
      full += fine.types[f] == CellType::full;
      fraction += fine.fractions[f];
      // Child q shares corner q with its parent.
      EXPECT_EQ(fine.points[fine.hexahedra[f][q]], coarse.points[coarse.hexahedra[c][q]]);
    }
    EXPECT_EQ(coarse.types[c] == CellType::full, full == 8);
    EXPECT_DOUBLE_EQ(coarse.fractions[c], fraction / 8);
  }
  for (int n : parentCount) EXPECT_EQ(n, 1);
  EXPECT_NEAR(coarse.filledVolume(), fine.filledVolume(), 1e-12);
  for (std::size_t e = 0; e < coarse.hexahedra.size(); ++e)
    EXPECT_NEAR(signedVolume(coarse.points, coarse.hexahedra[e]), coarse.box.spacing.prod(), 1e-12);
}

// --- Time to build
// ---------------------------------------------------------------------------------

TEST(SparseGrid, BuildsHundredThousandCellsQuickly) {
  // The time is printed, not asserted (DESIGN.md 5): the issue asks for 10^5 cells in under a
  // second. Sphere of 20480 triangles in 47 x 47 x 47 cells (103823).
  const TriangleSurface sphere = icosphere(5);
  for (int cells : {47, 100}) {
    const GridBox box = boxAround(Vec3d::Constant(-1), Vec3d::Constant(1), cells);
    const auto start = std::chrono::steady_clock::now();
    const SparseGrid grid = build(sphere, box);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ timing   ] %d^3 = %llu cells, %zu triangles: built in %.3f s (%zu kept)\n",
                cells, static_cast<unsigned long long>(box.cellCount()), sphere.triangles.size(),
                seconds, grid.cells.size());
    EXPECT_NEAR(grid.filledVolume(), sphere.volume(), 0.002 * sphere.volume());
  }
}

TEST(SparseGrid, BadInputIsReported) {
  const TriangleSurface cube = boxSurface(Vec3d::Zero(), Vec3d::Ones());
  SparseGrid grid;
  std::string error;
  GridBox box;
  box.cells = {0, 2, 2};
  EXPECT_FALSE(sparsegrid::buildSparseGrid({cube.points, cube.triangles}, box, 4, grid, error));
  EXPECT_NE(error.find("at least one cell"), std::string::npos) << error;
  box.cells = {2, 2, 2};
  std::vector<Triangle> bad = cube.triangles;
  bad[3][1] = 8;
  EXPECT_FALSE(sparsegrid::buildSparseGrid({cube.points, bad}, box, 4, grid, error));
  EXPECT_NE(error.find("triangle 3 uses point 8"), std::string::npos) << error;
}

}  // namespace
}  // namespace stroma::test
