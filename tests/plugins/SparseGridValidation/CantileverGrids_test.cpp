// SPDX-License-Identifier: MIT
// Seed 001, chapter 6 sections 2.1 and 3.1: the cantilever of 40 x 4 x 2 m (E = 20 kPa,
// density 1) under its weight, meshed by regular grids of hexahedra and tetrahedra and by sparse
// grids around its surface (aligned, rotated, oversized), solved statically with the
// corotational elements; tip deflection against beam theory (REFERENCES.md).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "GridFem.h"

namespace stroma::test {
namespace {

constexpr double kLength = 40, kWidth = 4, kHeight = 2;  // x, y, z (z up)
constexpr double kYoung = 20e3, kDensity = 1;
// Gravity reduced to 1e-5 m/s^2: a deflection of L / 83000, where the small-deflection theory
// holds (the seed's 9.81 m/s^2 bends this soft beam by more than its length). Newton's
// convergence with the corotational tangent (dR/dx ignored) slows down as the load grows on
// this slender beam: about 15 iterations at 1e-3 m/s^2, 2 to 4 here.
constexpr double kGravity = 1e-5;

/// Timoshenko's tip deflection of the cantilever under its weight (REFERENCES.md): q L^4 /
/// (8 E I) + q L^2 / (2 kappa G A), kappa = 10 (1 + nu) / (12 + 11 nu).
double beamTheory(double nu, double gravity) {
  const double area = kWidth * kHeight, inertia = kWidth * std::pow(kHeight, 3) / 12;
  const double q = kDensity * gravity * area, shear = kYoung / (2 * (1 + nu));
  const double kappa = 10 * (1 + nu) / (12 + 11 * nu);
  return q * std::pow(kLength, 4) / (8 * kYoung * inertia) +
         q * kLength * kLength / (2 * kappa * shear * area);
}

/// The beam in a grid's frame: beam point b is at frame * b in the grid's coordinates.
struct Placement {
  Mat3d frame = Mat3d::Identity();
};

/// Tip deflection (along the beam's -z) of the beam on `grid` (in the grid's coordinates, beam
/// placed by `placement`): grid nodes with beam x <= 0 fixed (the wall), the weight of the
/// cells' matter, static solve; the tip is the centre of the end face, embedded trilinearly.
double tipDeflection(const GridMesh& grid, const Placement& placement, const std::string& field,
                     const std::string& method, double nu, double gravity) {
  StaticProblem p;
  p.mesh = keepFilled(grid, 1e-6);
  p.forceField = field;
  p.method = method;
  p.youngModulus = kYoung;
  p.poissonRatio = nu;
  p.tolerance = 1e-5;  // on |R| / |R_0| or |du| / |U|: the deflection to about 1e-5
  const Vec3d down = placement.frame * Vec3d(0, 0, -1);
  addBodyForce(p, kDensity, gravity * down);
  for (std::size_t i = 0; i < p.mesh.points.size(); ++i)
    if ((placement.frame.transpose() * p.mesh.points[i]).x() <= 1e-9)
      p.fixed.push_back(static_cast<unsigned>(i));
  const auto tip = locate(p.mesh, placement.frame * Vec3d(kLength, 0, 0));
  EXPECT_TRUE(tip.has_value());
  if (!tip) return NAN;
  const StaticResult r = solveStatic(p);
  if (r.positions.empty()) return NAN;
  std::printf("  (%zu points, %zu cells, %d Newton iterations)\n", p.mesh.points.size(),
              p.mesh.hexahedra.size(), r.iterations);
  EXPECT_TRUE(r.converged) << field << " " << method << ": " << r.iterations
                           << " Newton iterations";
  return (interpolate(*tip, r.positions) - interpolate(*tip, p.mesh.points)).dot(down);
}

/// The regular grid of cells of width h filling the beam exactly.
GridMesh regularGrid(double h) {
  char xml[256];
  std::snprintf(xml, sizeof xml,
                "<RegularGridTopology name=\"grid\" min=\"0 %g %g\" max=\"%g %g %g\" "
                "n=\"%d %d %d\"/>",
                -kWidth / 2, -kHeight / 2, kLength, kWidth / 2, kHeight / 2,
                int(std::lround(kLength / h)) + 1, int(std::lround(kWidth / h)) + 1,
                int(std::lround(kHeight / h)) + 1);
  return buildGrid(xml);
}

// The beam's surface reaches 2 m into the wall (x < 0), so that the cells around the wall's
// plane hold matter on both sides whatever the grid's placement; grid nodes with x <= 0 are
// fixed.
constexpr double kInWall = 2;
Surface beamSurface() {
  return boxSurface(Vec3d(-kInWall, -kWidth / 2, -kHeight / 2),
                    Vec3d(kLength, kWidth / 2, kHeight / 2));
}

/// SparseGridTopology around the beam's surface placed by `placement`, cells of about h, on
/// the box of the placed surface grown by 1 % of each side (SOFA's default), or on that box
/// scaled about its centre by `oversize` when > 0 (then given as min and max).
std::string sparseGridXml(const Placement& placement, double h, double oversize = 0,
                          int finerLevels = 0) {
  const Surface s = transformed(beamSurface(), placement.frame, Vec3d::Zero());
  std::string box;
  Vec3d lo = s.points[0], hi = s.points[0];
  for (const Vec3d& q : s.points) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  Vec3d side = (hi - lo) * 1.02;
  if (oversize > 0) {
    const Vec3d centre = (lo + hi) / 2;
    side = (hi - lo) * oversize;
    lo = centre - side / 2;
    hi = centre + side / 2;
    box = " min=\"" + vecText(lo) + "\" max=\"" + vecText(hi) + "\"";
  }
  // An odd number of cells per axis: with a box centred on the beam, its faces never fall
  // on grid planes.
  Vec3i n;
  for (int a = 0; a < 3; ++a) n[a] = 2 * int(std::lround(side[a] / (2 * h))) + 2;
  char counts[64];
  std::snprintf(counts, sizeof counts, " n=\"%d %d %d\"", n.x(), n.y(), n.z());
  return "<SparseGridTopology name=\"grid\"" + std::string(counts) + box +
         " nbVirtualFinerLevels=\"" + std::to_string(finerLevels) + "\" " + surfaceAttributes(s) +
         "/>";
}

GridMesh sparseGrid(const Placement& placement, double h, double oversize = 0) {
  return buildGrid(sparseGridXml(placement, h, oversize));
}

/// Tip deflection with NonUniformHexahedronFEMForceFieldAndMass on the grid of
/// sparseGridXml(placement, h, oversize, levels): stiffness and mass condensed from `levels`
/// finer levels (seed 001 ch. 4 sec. 3), its own gravity; clamp and solve as tipDeflection.
double nonUniformTipDeflection(const Placement& placement, double h, double oversize, int levels) {
  const std::string grid = sparseGridXml(placement, h, oversize, levels);
  const GridMesh mesh = buildGrid(grid);
  std::vector<unsigned> fixed;
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    if ((placement.frame.transpose() * mesh.points[i]).x() <= 1e-9)
      fixed.push_back(static_cast<unsigned>(i));
  const auto tip = locate(mesh, placement.frame * Vec3d(kLength, 0, 0));
  EXPECT_TRUE(tip.has_value());
  if (!tip) return NAN;
  const Vec3d down = placement.frame * Vec3d(0, 0, -1);
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(
          scene,
          "<Node name=\"root\" dt=\"1\" gravity=\"" + vecText(kGravity * down) +
              "\">\n<Node name=\"body\">\n<StaticSolver name=\"solver\" newton_iterations=\"50\" "
              "absolute_correction_tolerance_threshold=\"0\" "
              "relative_correction_tolerance_threshold=\"1e-5\" "
              "absolute_residual_tolerance_threshold=\"0\" "
              "relative_residual_tolerance_threshold=\"1e-5\"/>\n<SparseLDLSolver/>\n" +
              grid +
              "\n<MechanicalObject name=\"dofs\"/>\n"
              "<NonUniformHexahedronFEMForceFieldAndMass method=\"large\" "
              "nbVirtualFinerLevels=\"" +
              std::to_string(levels) + "\" youngModulus=\"" + std::to_string(kYoung) +
              "\" poissonRatio=\"0\" density=\"" + std::to_string(kDensity) +
              "\"/>\n<FixedProjectiveConstraint indices=\"" + listText(fixed) +
              "\"/>\n</Node>\n</Node>\n"))
    return NAN;
  EXPECT_TRUE(scene.step()) << [&] {
    std::string text;
    for (const Message& m : scene.log().messages()) text += formatForConsole(m) + '\n';
    return text;
  }();
  EXPECT_EQ(objectAt<Base>(scene, "@/body/solver")->findData("lastConverged")->valueText(), "1");
  const auto& x =
      objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs")->readCoord(VecId::position());
  return (interpolate(*tip, x) - interpolate(*tip, mesh.points)).dot(down);
}

/// Deflection / theory at cells of 2, 1 and 0.5 m (1, 2 and 4 cells through the height) of
/// the regular grid, printed.
std::vector<double> regularRatios(const char* field, const char* method) {
  std::vector<double> ratios;
  for (double h : {2.0, 1.0, 0.5}) {
    ratios.push_back(tipDeflection(regularGrid(h), {}, field, method, 0, kGravity) /
                     beamTheory(0, kGravity));
    std::printf("%s %s, regular grid, h = %g m: deflection / theory = %.4f\n", field, method, h,
                ratios.back());
  }
  return ratios;
}

/// Each deviation from 1 below its tolerance, and shrinking by at least `rate` per halving.
void checkConvergence(const std::vector<double>& ratios, const std::array<double, 3>& tolerance,
                      double rate) {
  for (std::size_t level = 0; level < ratios.size(); ++level) {
    const double deviation = std::abs(1 - ratios[level]);
    EXPECT_LT(deviation, tolerance[level]) << "level " << level;
    if (level > 0) {
      EXPECT_GT(std::abs(1 - ratios[level - 1]) / deviation, rate) << "level " << level;
    }
  }
}

TEST(CantileverGrids, RegularHexahedraConvergeToBeamTheory) {
  // nu = 0: no Poisson effect at the clamp, the case the 1D theory describes; reference
  // 4.8096e-4 m (Euler-Bernoulli 4.8000e-4, shear 9.6e-7). Measured deflection / theory, large
  // and polar alike (the load is small): 0.6670, 0.8888, 0.9696; the deviation shrinks 3.0 and
  // 3.7 times per halving of h; Richardson's extrapolation of the two finest (second order)
  // gives 0.9965.
  const std::vector<double> large = regularRatios("HexahedronFEMForceField", "large");
  checkConvergence(large, {0.36, 0.13, 0.04}, 2.5);
  EXPECT_NEAR(large[2] + (large[2] - large[1]) / 3, 1, 0.01);
  const double polar =
      tipDeflection(regularGrid(0.5), {}, "HexahedronFEMForceField", "polar", 0, kGravity) /
      beamTheory(0, kGravity);
  EXPECT_NEAR(polar, large[2], 1e-4);
}

TEST(CantileverGrids, RegularTetrahedraConvergeToBeamTheory) {
  // The same grids split into 6 tetrahedra per cell. Linear tetrahedra lock in bending: measured
  // deflection / theory 0.2367, 0.5425, 0.8224 (large and polar alike), the deviation shrinking
  // 1.7 and 2.6 times per halving; a few % needs about 8 cells through the height
  // (FemValidation_test: 0.93 there), which this test leaves to that one for its cost.
  const std::vector<double> large = regularRatios("TetrahedronFEMForceField", "large");
  checkConvergence(large, {0.80, 0.50, 0.20}, 1.5);
  const double polar =
      tipDeflection(regularGrid(0.5), {}, "TetrahedronFEMForceField", "polar", 0, kGravity) /
      beamTheory(0, kGravity);
  EXPECT_NEAR(polar, large[2], 1e-4);
}

TEST(CantileverGrids, CorotationalVariantsAgreeForAFixedPoissonRatio) {
  // nu = 0.3, cells of 0.5 m (4 through the height), the small load. QR (large) and polar give
  // the same deflection for a given element to 1e-4 (measured: identical to 4 digits); the
  // tetrahedra stay stiffer than the hexahedra by their discretization error at this
  // resolution (shear locking: see RegularTetrahedraConvergeToBeamTheory). Measured deflection
  // / theory: hexahedra 0.9571, tetrahedra 0.7841 (ratio 0.819). A large deflection (30 times
  // the load, 3 % of L) was not reached: StaticSolver's Newton stalls on this slender beam, its
  // corotational tangent ignoring dR/dx (README.md).
  struct Variant {
    const char* field;
    const char* method;
  };
  const Variant variants[] = {{"HexahedronFEMForceField", "large"},
                              {"HexahedronFEMForceField", "polar"},
                              {"TetrahedronFEMForceField", "large"},
                              {"TetrahedronFEMForceField", "polar"}};
  const GridMesh grid = regularGrid(0.5);
  std::vector<double> ratios;
  for (const Variant& v : variants) {
    ratios.push_back(tipDeflection(grid, {}, v.field, v.method, 0.3, kGravity) /
                     beamTheory(0.3, kGravity));
    std::printf("%s %s, nu = 0.3: deflection / theory = %.4f\n", v.field, v.method, ratios.back());
  }
  EXPECT_NEAR(ratios[1], ratios[0], 1e-4);
  EXPECT_NEAR(ratios[3], ratios[2], 1e-4);
  EXPECT_NEAR(ratios[0], 1, 0.05);
  EXPECT_NEAR(ratios[2] / ratios[0], 0.82, 0.03);
}

TEST(CantileverGrids, AlignedSparseGridConvergesToBeamTheory) {
  // SparseGridTopology around the beam's surface with SOFA's box (the surface's grown by 1 %),
  // an odd number of cells of about 2, 1, 0.5 m per axis: the outer layer of cells is partly
  // filled, and the wall's plane x = 0 cuts cells, so the clamp lies between the last fixed
  // grid plane and x = 0 (an error of order h / L). Hexahedra large, nu = 0. Measured
  // deflection / theory: 0.7231, 0.9045, 0.9950.
  const double reference = beamTheory(0, kGravity);
  std::vector<double> ratios;
  for (double h : {2.0, 1.0, 0.5}) {
    ratios.push_back(
        tipDeflection(sparseGrid({}, h), {}, "HexahedronFEMForceField", "large", 0, kGravity) /
        reference);
    std::printf("sparse grid, aligned, h = %g: deflection / theory = %.4f\n", h, ratios.back());
  }
  checkConvergence(ratios, {0.32, 0.12, 0.03}, 2.0);
}

/// Deflection of the beam in the aligned sparse grid, cells of about 0.5 m.
double alignedDeflection() {
  return tipDeflection(sparseGrid({}, 0.5), {}, "HexahedronFEMForceField", "large", 0, kGravity);
}

TEST(CantileverGrids, RotatedGridStaysCloseToTheAlignedOne) {
  // Cells of about 0.5 m. The beam turned by 30 degrees about its axis, then by 30 degrees
  // about the vertical, in the grid (the grid's box is the turned surface's grown by 1 %):
  // every face cuts cells at varying depths, the wall's plane too. Boundary cells weigh their
  // filled fraction (E and weight). Measured deflection / theory: aligned 0.9950, rotated
  // 0.9295 (6.6 % stiffer: a cell cut by a face spreads its matter over the whole cell, which
  // here lies partly further from the neutral axis, and the clamp's cells are cut obliquely).
  const double aligned = alignedDeflection();
  Placement rotated;
  rotated.frame =
      (Eigen::AngleAxisd(M_PI / 6, Vec3d::UnitZ()) * Eigen::AngleAxisd(M_PI / 6, Vec3d::UnitX()))
          .toRotationMatrix();
  const double turned = tipDeflection(sparseGrid(rotated, 0.5), rotated, "HexahedronFEMForceField",
                                      "large", 0, kGravity);
  std::printf("aligned %.4f, rotated %.4f (deflection / theory)\n",
              aligned / beamTheory(0, kGravity), turned / beamTheory(0, kGravity));
  EXPECT_NEAR(turned / aligned, 1, 0.10);
}

TEST(CantileverGrids, OversizedGridStaysCloseToTheAlignedOne) {
  // The grid's box 1.5 times the surface's, centred on it, cells of about 0.5 m, an odd number
  // per axis so that every face of the beam cuts cells. Measured deflection / theory: aligned
  // 0.9950, oversized 0.9181 (7.7 % stiffer, for the same reasons as the rotated grid).
  const double aligned = alignedDeflection();
  const double oversized =
      tipDeflection(sparseGrid({}, 0.5, 1.5), {}, "HexahedronFEMForceField", "large", 0, kGravity);
  std::printf("aligned %.4f, oversized %.4f (deflection / theory)\n",
              aligned / beamTheory(0, kGravity), oversized / beamTheory(0, kGravity));
  EXPECT_NEAR(oversized / aligned, 1, 0.10);
}

TEST(CantileverGrids, FinerLevelsBringTheOversizedGridCloser) {
  // Cells of about 1 m, NonUniformHexahedronFEMForceFieldAndMass (plugins/NonUniformFEM) with
  // its own gravity. Without finer levels it must equal this file's fraction weighting; with
  // one finer level (fractions measured on cells of 0.5 m, stiffness and mass condensed) the
  // oversized grid's deflection comes close to the aligned one. Measured deflection / theory:
  // aligned 0.9045 (fractions; the same as tipDeflection to 1e-4), 0.9143 (1 level); oversized
  // 0.8467 (fractions, 6.4 % stiffer than aligned), 0.9241 (1 level, 1.1 % softer).
  // The rotated grid is not in this test: it keeps cells of zero fraction (touched by the
  // surface only) whose own corners then have neither stiffness nor mass, and SparseLDLSolver
  // reports the system singular (tipDeflection drops those cells).
  const double reference = beamTheory(0, kGravity);
  const double fractions =
      tipDeflection(sparseGrid({}, 1), {}, "HexahedronFEMForceField", "large", 0, kGravity);
  const double aligned0 = nonUniformTipDeflection({}, 1, 0, 0);
  const double aligned1 = nonUniformTipDeflection({}, 1, 0, 1);
  const double oversized0 = nonUniformTipDeflection({}, 1, 1.5, 0);
  const double oversized1 = nonUniformTipDeflection({}, 1, 1.5, 1);
  std::printf(
      "cells of 1 m, deflection / theory: aligned %.4f (E x fraction), %.4f (non-uniform, "
      "0 levels), %.4f (1 level); oversized %.4f (0 levels), %.4f (1 level)\n",
      fractions / reference, aligned0 / reference, aligned1 / reference, oversized0 / reference,
      oversized1 / reference);
  EXPECT_NEAR(aligned0 / fractions, 1, 1e-3);
  EXPECT_NEAR(oversized1 / aligned1, 1, 0.02);
  EXPECT_LT(std::abs(oversized1 / aligned1 - 1), std::abs(oversized0 / aligned0 - 1) / 3);
}

}  // namespace
}  // namespace stroma::test
