// SPDX-License-Identifier: MIT
// Seed 001, chapter 6 section 3.2.2: a cylinder of nearly incompressible matter (nu = 0.49)
// compressed along its axis by 10, 20 and 30 % between frictionless plates, meshed by a sparse
// grid of hexahedra centred on it and by one offset by a fraction of a cell. The mid-plane must
// stay circular: the standard deviation of its points' radii under 0.3 % of their mean.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "GridFem.h"

namespace stroma::test {
namespace {

constexpr double kRadius = 0.5, kHeight = 1.0, kCell = 0.1, kNu = 0.49;
constexpr int kSegments = 64, kRings = 8;  // ring kRings / 2 is the mid-plane
// Cells 1/6 m tall: the cylinder is a prism along z, and 6 layers keep the test fast.
constexpr int kLayers = 6;

/// The sparse grid around the cylinder, cells of kCell across and kHeight / kLayers along the
/// axis, the box offset across the axis by `offset` (in cells). Its bottom and top planes are
/// the cylinder's end faces, where the plates act.
GridMesh cylinderGrid(const Vec2d& offset) {
  const Surface s = cylinderSurface(kRadius, kHeight, kSegments, kRings);
  // 11 cells across (the axis mid-cell), or 12 when offset so that the box still holds it.
  const bool centred = offset.isZero();
  const int across = centred ? 11 : 12;
  const Vec3d lo((offset.x() - across / 2.0) * kCell, (offset.y() - across / 2.0) * kCell, 0);
  const Vec3d hi = lo + Vec3d(across * kCell, across * kCell, kHeight);
  return keepFilled(
      buildGrid("<SparseGridTopology name=\"grid\" n=\"" + std::to_string(across + 1) + " " +
                std::to_string(across + 1) + " " + std::to_string(kLayers + 1) + "\" min=\"" +
                vecText(lo) + "\" max=\"" + vecText(hi) + "\" " + surfaceAttributes(s) + "/>"),
      1e-6);
}

struct RadiusStatistics {
  double mean = 0, deviation = 0, min = 1e300, max = 0;
};

/// Frictionless plates let the end faces slide across the axis; bonded ones hold them.
enum class Plates { frictionless, bonded };

/// Compresses the cylinder's grid by `strain` and returns the radii of the mid-plane ring of
/// the surface (embedded trilinearly), about the ring's centroid.
RadiusStatistics compress(const GridMesh& grid, double strain, Plates plates) {
  StaticProblem p;
  p.mesh = grid;
  p.method = "polar";
  p.tolerance = 1e-6;
  p.youngModulus = 1e4;
  p.poissonRatio = kNu;
  // Frictionless plates: the end planes' nodes move only across the axis. One bottom node
  // (the nearest to the axis) fixed, and a second one of the same x fixed along x, remove the
  // rigid motions without restraining the lateral expansion.
  StaticProblem::Partial ends{{}, {0, 0, 1}}, pin{{}, {1, 1, 1}}, roller{{}, {1, 0, 0}};
  if (plates == Plates::bonded) ends.directions = {1, 1, 1};
  unsigned centre = 0;
  double best = 1e300;
  for (unsigned i = 0; i < grid.points.size(); ++i) {
    const Vec3d& q = grid.points[i];
    if (q.z() < 1e-9 || q.z() > kHeight - 1e-9) ends.indices.push_back(i);
    if (q.z() < 1e-9 && q.head<2>().norm() < best) {
      best = q.head<2>().norm();
      centre = i;
    }
  }
  const Vec3d c = grid.points[centre];
  unsigned far = centre;
  for (unsigned i = 0; i < grid.points.size(); ++i) {
    const Vec3d& q = grid.points[i];
    if (q.z() < 1e-9 && std::abs(q.x() - c.x()) < 1e-9 &&
        std::abs(q.y() - c.y()) > std::abs(grid.points[far].y() - c.y()))
      far = i;
  }
  pin.indices = {centre};
  roller.indices = {far};
  p.partial = {ends};
  if (plates == Plates::frictionless) {
    p.partial.push_back(pin);
    p.partial.push_back(roller);
  }
  // The top plate's travel imposed on the initial positions (the whole grid squeezed
  // uniformly, a starting point for Newton).
  for (const Vec3d& q : grid.points) p.initial.emplace_back(q.x(), q.y(), q.z() * (1 - strain));
  const StaticResult r = solveStatic(p);
  RadiusStatistics stats;
  if (r.positions.empty()) return stats;
  EXPECT_TRUE(r.converged) << strain;

  std::vector<Vec3d> ring;
  for (int i = 0; i < kSegments; ++i) {
    const double a = 2 * M_PI * i / kSegments;
    const auto e = locate(grid, Vec3d(kRadius * std::cos(a), kRadius * std::sin(a), kHeight / 2));
    EXPECT_TRUE(e.has_value());
    if (e) ring.push_back(interpolate(*e, r.positions));
  }
  Vec3d centroid = Vec3d::Zero();
  for (const Vec3d& q : ring) centroid += q / double(ring.size());
  std::vector<double> radii;
  for (const Vec3d& q : ring) radii.push_back((q - centroid).head<2>().norm());
  for (double rad : radii) {
    stats.mean += rad / double(radii.size());
    stats.min = std::min(stats.min, rad);
    stats.max = std::max(stats.max, rad);
  }
  for (double rad : radii)
    stats.deviation += (rad - stats.mean) * (rad - stats.mean) / double(radii.size());
  stats.deviation = std::sqrt(stats.deviation);
  return stats;
}

/// The three compressions in the centred and the offset grid: prints the mid-plane radii,
/// checks that they stay on a circle (standard deviation under `maxDeviation` of their mean)
/// and that the cylinder bulges at least as much as the linear estimate R (1 + nu e).
void checkCircularity(Plates plates, double maxDeviation) {
  const char* platesName = plates == Plates::bonded ? "bonded" : "frictionless";
  const char* names[] = {"centred", "offset"};
  const Vec2d offsets[] = {Vec2d(0, 0), Vec2d(0.3, 0.45)};
  for (int g = 0; g < 2; ++g) {
    const GridMesh grid = cylinderGrid(offsets[g]);
    ASSERT_FALSE(grid.hexahedra.empty());
    for (double strain : {0.1, 0.2, 0.3}) {
      const RadiusStatistics s = compress(grid, strain, plates);
      std::printf(
          "%s plates, %s grid, %2.0f %%: mean radius %.5f m (x %.4f; R (1 + nu e) x %.4f, "
          "incompressible x %.4f), min %.5f, max %.5f, std %.6f m = %.4f %%\n",
          platesName, names[g], 100 * strain, s.mean, s.mean / kRadius, 1 + kNu * strain,
          1 / std::sqrt(1 - strain), s.min, s.max, s.deviation, 100 * s.deviation / s.mean);
      EXPECT_LT(s.deviation, maxDeviation * s.mean) << names[g] << " " << strain;
      EXPECT_GT(s.mean, kRadius * (1 + kNu * strain) - 1e-4) << names[g] << " " << strain;
    }
  }
}

TEST(CylinderCompression, FrictionlessPlatesKeepTheMidPlaneCircular) {
  // Polar hexahedra (large gives the same radii to 1e-5 m). With frictionless plates the
  // exact solution is a uniform uniaxial stress: no lateral stress, and every column of cells
  // along the axis has the same fraction, so the boundary cells' weights do not disturb it.
  // Measured: mean radius x 1.0490, 1.0980, 1.1470 (= 1 + nu e: the corotational elements are
  // linear in the stretch; an incompressible matter would give x 1.0541, 1.1180, 1.1952),
  // standard deviation 0.0006 to 0.0026 % of the radius in both grids.
  checkCircularity(Plates::frictionless, 0.003);
}

TEST(CylinderCompression, BondedPlatesKeepTheMidPlaneCircular) {
  // The ends held by the plates: the cylinder barrels, the mid-plane bulges beyond R (1 + nu e)
  // and its circularity depends on how the grid's cells follow the surface (seed 001 table
  // 6.2: Ansys 0.53311, 0.56621, 0.59932; sparse grid centred 0.54353, 0.58357, 0.61947 with a
  // standard deviation of 0.16, 0.28, 0.36 % of the mean). Measured mean radius: 0.53372,
  // 0.56678, 0.59912 m in both grids (within 0.11 % of Ansys'), standard deviation 0.014, 0.032,
  // 0.054 % (centred) and 0.011, 0.027, 0.048 % (offset) of the mean.
  checkCircularity(Plates::bonded, 0.003);
}

}  // namespace
}  // namespace stroma::test
