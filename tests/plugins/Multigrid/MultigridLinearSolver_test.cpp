// SPDX-License-Identifier: MIT
// MultigridLinearSolver on the cantilever of seed 001 table 5.2 (E = 40000, nu = 0.3, clamped
// at x = 0, huge gravity), here on 16^3 hexahedra so that the test stays fast on one core (the
// 32^3 case is bench/MultigridBenchmarks.cpp): one V-cycle of MG4 is far more accurate than 150
// CG iterations; cycling converges to the direct solution; an implicit Euler run follows
// SparseLDL's trajectory; bad input is reported by field, without a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "MultigridScenes.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"

namespace stroma::test {
namespace {

const Vec3i kCells16{16, 16, 16};

std::string mg(int levels, const std::string& extra = "", const std::string& name = "mg") {
  return "<MultigridLinearSolver name=\"" + name + std::to_string(levels) + "\" levels=\"" +
         std::to_string(levels) + "\" iterations=\"1\" tolerance=\"0\" " + extra + "/>\n";
}

// Table 5.2 on 16^3 cells (bending under 10^6 g): reference = CG to a relative residual of
// 1e-13; CGfast = 10 CG iterations, CG20 = 20 (about the work of one MG4 V-cycle: 7 + 7
// smoothing products and a residual on the fine level, an eighth of that per coarser level);
// MGk = one V-cycle with k coarse levels (7 smoothing iterations, 150 at the coarsest), FMG4 one
// full cycle. The bounds are the errors measured on this grid (Release) with a margin of about
// 1.5x, so that a wrong transfer or operator fails. On 16^3, 150 CG iterations already reach
// 2e-6 (CG needs about twice as many iterations on 32^3): the comparison with CGmax is made on
// 32^3 in bench/MultigridBenchmarks.cpp.
TEST(MultigridLinearSolver, OneCycleOnTheCantileverOfTable52) {
  const std::string cg = R"(template="CompressedRowSparseMatrixMat3x3d" threshold="1e-300" )";
  const std::string solvers =
      "<CGLinearSolver name=\"reference\" iterations=\"5000\" tolerance=\"1e-13\" " + cg +
      "/>\n<CGLinearSolver name=\"cg10\" tolerance=\"0\" iterations=\"10\" " + cg +
      "/>\n<CGLinearSolver name=\"cg20\" tolerance=\"0\" iterations=\"20\" " + cg + "/>\n" + mg(1) +
      mg(2) + mg(4) + mg(4, "cycle=\"full\"", "fmg");
  LoadedScene s(cantileverScene(kCells16, 2.0, 40000, 0.3, solvers));
  ASSERT_TRUE(s.loaded) << s.log();
  std::vector<LinearSolveReport> reports;
  const std::vector<Eigen::VectorXd> u = solveStatic(s, &reports);
  ASSERT_EQ(u.size(), 7u);
  ASSERT_TRUE(reports[0].converged);
  const Eigen::VectorXd& reference = u[0];
  ASSERT_GT(reference.norm(), 0);
  const double cg10 = relativeError(u[1], reference), cg20 = relativeError(u[2], reference);
  const double mg1 = relativeError(u[3], reference), mg2 = relativeError(u[4], reference);
  const double mg4 = relativeError(u[5], reference), fmg4 = relativeError(u[6], reference);
  std::printf("relative errors: CG10 %.3g CG20 %.3g MG1 %.3g MG2 %.3g MG4 %.3g FMG4 %.3g\n", cg10,
              cg20, mg1, mg2, mg4, fmg4);
  EXPECT_GT(cg10, 0.8);  // 10 iterations barely start the deflection
  EXPECT_LT(mg1, 0.03);
  EXPECT_LT(mg2, 0.1);
  EXPECT_LT(mg4, 0.36);
  EXPECT_LT(fmg4, 0.025);
  EXPECT_LT(mg4, 0.5 * cg20);  // better than plain CG for the same work
  EXPECT_LT(fmg4, 0.05 * cg20);
}

// The 32^3 cantilever of seed 001 table 5.2 (32768 hexahedra, 35937 nodes, bending under
// 10^6 g) in optimized builds only: about 4 s of one core in Release, minutes under the
// sanitizers or without optimization.
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define STROMA_MULTIGRID_32_CUBED 0
#endif
#endif
#ifndef STROMA_MULTIGRID_32_CUBED
#define STROMA_MULTIGRID_32_CUBED 1
#endif
#else
#define STROMA_MULTIGRID_32_CUBED 0
#endif

// Issue 5's multigrid target on table 5.2's problem: one full cycle (2 CG smoothing iterations
// before and after each coarse correction, LDL^T on the coarsest of 4 coarse levels) reaches
// the error of 150 CG iterations (4.43 % here) with a margin (measured 2.17 %), and so does the
// nested cycle of the report that only interpolates on the fine level (bench/README.md,
// Table52Assembled).
TEST(MultigridLinearSolver, OneCheapFullCycleReachesTheErrorOf150CGIterationsOn32Cubed) {
  if (!STROMA_MULTIGRID_32_CUBED) GTEST_SKIP() << "32^3 grid: optimized, unsanitized builds only";
  const std::string solvers =
      "<MultigridLinearSolver name=\"reference\" levels=\"4\" conjugateGradient=\"true\" "
      "iterations=\"100\" tolerance=\"1e-11\"/>\n"
      "<CGLinearSolver name=\"cg150\" tolerance=\"0\" iterations=\"150\" "
      "template=\"CompressedRowSparseMatrixMat3x3d\" threshold=\"1e-300\"/>\n"
      "<MultigridLinearSolver name=\"fmg\" levels=\"4\" cycle=\"full\" iterations=\"1\" "
      "tolerance=\"0\" smoothingIterations=\"2\" directCoarseSolve=\"true\"/>\n"
      "<MultigridLinearSolver name=\"nested\" levels=\"4\" cycle=\"full\" iterations=\"1\" "
      "tolerance=\"0\" levelCycles=\"0 1\" levelSmoothing=\"0 3\" postSmoothing=\"false\" "
      "directCoarseSolve=\"true\" matrixPrecision=\"single\"/>\n";
  LoadedScene s(cantileverScene(Vec3i(32, 32, 32), 2.0, 40000, 0.3, solvers));
  ASSERT_TRUE(s.loaded) << s.log();
  std::vector<LinearSolveReport> reports;
  const std::vector<Eigen::VectorXd> u = solveStatic(s, &reports);
  ASSERT_EQ(u.size(), 4u);
  ASSERT_TRUE(reports[0].converged);
  const double cg150 = relativeError(u[1], u[0]), fmg = relativeError(u[2], u[0]);
  const double nested = relativeError(u[3], u[0]);
  std::printf("32^3 relative errors: CG150 %.4g, FMG4 (2 smoothing, LDL) %.4g, nested (fine "
              "level interpolated, 3 pre-smoothing iterations, single) %.4g\n",
              cg150, fmg, nested);
  EXPECT_GT(cg150, 0.04);  // 150 iterations are far from converged on this grid
  EXPECT_LT(cg150, 0.05);
  EXPECT_LT(fmg, 0.6 * cg150);
  // The fast setting of the report (measured 2.93 %, 174 times faster than CG150 with the same
  // single-precision blocks, 411 times faster than CG150 on Eigen's matrix; bench/README.md):
  // no work on the fine level but the two transfers, the 16^3 level by a full cycle of 3
  // pre-smoothing iterations per level in single precision.
  EXPECT_LT(nested, 0.8 * cg150);
}

// The nested cycles on 16^3 (bounds: the measured errors with a margin of about 1.5x). A full
// cycle whose fine level only receives the prolongation of the 8^3 level's full cycle is
// limited by the 8^3 discretization; a cascadic cycle with CG on every level (4 on the fine
// one, 16 below) is far better than 4 + 16 plain CG iterations; level matrices in single
// precision leave a full cycle as accurate. (They do not leave it the same to 1e-6: a few CG
// iterations are not a linear function of the matrix, and the cycle's result moves by 1e-5
// to 2e-3 of the solution under perturbations of the matrices of 1e-15 to 1e-7.)
TEST(MultigridLinearSolver, NestedCyclesOnTheCantilever) {
  const std::string solvers =
      "<CGLinearSolver name=\"reference\" iterations=\"5000\" tolerance=\"1e-13\" "
      "template=\"CompressedRowSparseMatrixMat3x3d\" threshold=\"1e-300\"/>\n"
      "<CGLinearSolver name=\"cg20\" iterations=\"20\" tolerance=\"0\" "
      "template=\"CompressedRowSparseMatrixMat3x3d\" threshold=\"1e-300\"/>\n" +
      mg(4, "cycle=\"full\" levelCycles=\"0 1\" directCoarseSolve=\"true\"", "interpolated") +
      mg(4, "cycle=\"cascadic\" levelSmoothing=\"4 16\" directCoarseSolve=\"true\"",
         "cascadic") +
      mg(4, "cycle=\"full\" directCoarseSolve=\"true\"", "fmg") +
      mg(4, "cycle=\"full\" directCoarseSolve=\"true\" matrixPrecision=\"single\"", "single");
  LoadedScene s(cantileverScene(kCells16, 2.0, 40000, 0.3, solvers));
  ASSERT_TRUE(s.loaded) << s.log();
  const std::vector<Eigen::VectorXd> u = solveStatic(s);
  ASSERT_EQ(u.size(), 6u);
  const double cg20 = relativeError(u[1], u[0]), interpolated = relativeError(u[2], u[0]);
  const double cascadic = relativeError(u[3], u[0]), fmg = relativeError(u[4], u[0]);
  std::printf("relative errors: CG20 %.3g, fine level interpolated %.3g, cascadic (4, 16) %.3g, "
              "FMG4 %.3g, FMG4 single %.3g (from the double: %.3g)\n",
              cg20, interpolated, cascadic, fmg, relativeError(u[5], u[0]),
              relativeError(u[5], u[4]));
  EXPECT_GT(interpolated, fmg);  // the fine level's own V-cycle does help
  EXPECT_LT(interpolated, 0.1);
  EXPECT_LT(cascadic, 0.25 * cg20);
  // Both full cycles within the bound of OneCycleOnTheCantileverOfTable52 (measured 1.5 % and
  // 1.7 %).
  EXPECT_LT(fmg, 0.025);
  EXPECT_LT(relativeError(u[5], u[0]), 0.025);
}

// Repeated V-cycles converge: measured 16 cycles of MG4 to a relative residual of 1e-8 on this
// grid (a reduction of about 3 per cycle), 9 for MG1; as the preconditioner of a flexible CG,
// MG4 needs 10 iterations.
TEST(MultigridLinearSolver, VCyclesConvergeOnTheCantilever) {
  const std::string solvers =
      "<MultigridLinearSolver name=\"mg4\" levels=\"4\" iterations=\"40\" tolerance=\"1e-8\"/>\n"
      "<MultigridLinearSolver name=\"mg1\" levels=\"1\" iterations=\"40\" tolerance=\"1e-8\"/>\n"
      "<MultigridLinearSolver name=\"fcg\" levels=\"4\" iterations=\"40\" tolerance=\"1e-8\" "
      "conjugateGradient=\"true\"/>\n";
  LoadedScene s(cantileverScene(kCells16, 2.0, 40000, 0.3, solvers));
  ASSERT_TRUE(s.loaded) << s.log();
  std::vector<LinearSolveReport> reports;
  const std::vector<Eigen::VectorXd> u = solveStatic(s, &reports);
  ASSERT_EQ(u.size(), 3u);
  std::printf("iterations to 1e-8: MG4 %d, MG1 %d, MG4-FCG %d\n", reports[0].iterations,
              reports[1].iterations, reports[2].iterations);
  EXPECT_TRUE(reports[2].converged);
  EXPECT_LE(reports[2].iterations, 12);
  EXPECT_LT(relativeError(u[2], u[1]), 1e-8);
  EXPECT_TRUE(reports[0].converged);
  EXPECT_TRUE(reports[1].converged);
  EXPECT_LE(reports[0].iterations, 20);
  EXPECT_LE(reports[1].iterations, 12);
  EXPECT_LT(relativeError(u[0], u[1]), 1e-8);
}

TEST(MultigridLinearSolver, CyclesConvergeToTheDirectSolution) {
  const std::string solvers =
      "<SparseLDLSolver name=\"ldl\"/>\n"
      "<MultigridLinearSolver name=\"mg\" levels=\"3\" iterations=\"30\" tolerance=\"1e-10\"/>\n"
      "<MultigridLinearSolver name=\"direct\" levels=\"2\" directCoarseSolve=\"true\" "
      "iterations=\"30\" tolerance=\"1e-10\"/>\n"
      "<MultigridLinearSolver name=\"fcg\" levels=\"3\" conjugateGradient=\"true\" "
      "cycle=\"full\" iterations=\"30\" tolerance=\"1e-10\"/>\n";
  LoadedScene s(cantileverScene(Vec3i(8, 4, 4), 2.0, 40000, 0.3, solvers));
  ASSERT_TRUE(s.loaded) << s.log();
  std::vector<LinearSolveReport> reports;
  const std::vector<Eigen::VectorXd> u = solveStatic(s, &reports);
  ASSERT_EQ(u.size(), 4u);
  for (int k : {1, 2, 3}) {
    EXPECT_TRUE(reports[k].converged);
    EXPECT_LE(reports[k].residual, 1e-10);
    EXPECT_LT(reports[k].iterations, 30);
    EXPECT_LT(relativeError(u[k], u[0]), 1e-7);
  }
  // The clamped points do not move.
  const auto& rest = s.body().get<MechanicalState<Vec3Types>>()->readCoord(VecId::restPosition());
  for (std::size_t i = 0; i < rest.size(); ++i)
    if (rest[i].x() == 0) {
      for (int a = 0; a < 3; ++a) EXPECT_EQ(u[1][3 * Eigen::Index(i) + a], 0.0);
    }
}

// A SparseGridTopology around an octahedron (boundary cells, empty cells dropped, so the coarse
// levels have partial cells): the grid's own box is used, the levels are built down to the
// requested count, and the preconditioned cycles reach SparseLDL's solution of an implicit-Euler
// system (A = M - h^2 K, h = 0.1).
TEST(MultigridLinearSolver, SolvesOnASparseGridTopology) {
  const std::string xml =
      "<Node name=\"root\" gravity=\"0 -9.81 0\"><Node name=\"Body\">"
      "<SparseGridTopology name=\"grid\" n=\"13 13 13\" position=\"1 0 0  -1 0 0  0 1 0  "
      "0 -1 0  0 0 1  0 0 -1\" triangles=\"0 2 4  2 1 4  1 3 4  3 0 4  2 0 5  1 2 5  3 1 5  "
      "0 3 5\"/>"
      "<SparseLDLSolver name=\"ldl\"/>"
      "<MultigridLinearSolver name=\"mg\" levels=\"3\" conjugateGradient=\"true\" "
      "iterations=\"40\" tolerance=\"1e-10\"/>"
      "<MechanicalObject name=\"dofs\"/><UniformMass totalMass=\"1\"/>"
      "<BoxROI name=\"left\" box=\"-2 -2 -2  -0.5 2 2\" position=\"@dofs.rest_position\"/>"
      "<FixedProjectiveConstraint indices=\"@left.indices\"/>"
      "<HexahedronFEMForceField youngModulus=\"1000\" poissonRatio=\"0.3\"/>"
      "</Node></Node>";
  LoadedScene s(xml);
  ASSERT_TRUE(s.loaded) << s.log();
  std::vector<LinearSolveReport> reports;
  const std::vector<Eigen::VectorXd> u = solveStatic(s, &reports, 1.0, -0.01);
  ASSERT_EQ(u.size(), 2u);
  EXPECT_EQ(s.body().findObject("mg")->findData("levelCount")->valueText(), "4");
  EXPECT_TRUE(reports[1].converged);
  EXPECT_LT(relativeError(u[1], u[0]), 1e-8);
  EXPECT_GT(u[0].norm(), 0);
}

TEST(MultigridLinearSolver, ImplicitEulerFollowsSparseLDL) {
  auto run = [](const std::string& solver) {
    LoadedScene s(cantileverScene(Vec3i(8, 4, 4), 2.0, 4000, 0.3,
                                  "<EulerImplicitSolver rayleighStiffness=\"0.1\" "
                                  "rayleighMass=\"0.1\"/>\n" +
                                      solver,
                                  "large", 9.81, 10.0, 0.02));
    EXPECT_TRUE(s.loaded) << s.log();
    for (int n = 0; n < 20; ++n) EXPECT_TRUE(s.scene->step()) << s.log();
    EXPECT_EQ(s.log(), "");
    return s.body().get<MechanicalState<Vec3Types>>()->readCoord(VecId::position());
  };
  const std::vector<Vec3d> ldl = run("<SparseLDLSolver/>");
  const std::vector<Vec3d> multigrid =
      run("<MultigridLinearSolver levels=\"2\" iterations=\"50\" tolerance=\"1e-10\"/>");
  ASSERT_EQ(ldl.size(), multigrid.size());
  double difference = 0, tipDrop = 0;
  for (std::size_t i = 0; i < ldl.size(); ++i) {
    difference = std::max(difference, (ldl[i] - multigrid[i]).norm());
    tipDrop = std::max(tipDrop, -ldl[i].y());
  }
  EXPECT_GT(tipDrop, 1e-3);  // the beam bent
  EXPECT_LT(difference, 1e-7 * (1 + tipDrop));
}

// Coarse operators kept from the first step (coarseUpdateInterval = 0: the corotational
// matrix changes at every step, the coarse levels do not follow) and each solve started from
// the previous one's solution: the outer flexible CG still reaches the tolerance at every step
// and the trajectory is SparseLDL's; updating the coarse operators every 5 steps as well.
TEST(MultigridLinearSolver, StaleCoarseOperatorsAndWarmStartFollowSparseLDL) {
  auto run = [](const std::string& solver, int* iterations) {
    LoadedScene s(cantileverScene(Vec3i(8, 4, 4), 2.0, 4000, 0.3,
                                  "<EulerImplicitSolver rayleighStiffness=\"0.1\" "
                                  "rayleighMass=\"0.1\"/>\n" +
                                      solver,
                                  "large", 9.81, 10.0, 0.02));
    EXPECT_TRUE(s.loaded) << s.log();
    for (int n = 0; n < 20; ++n) {
      EXPECT_TRUE(s.scene->step()) << s.log();
      if (iterations)
        *iterations +=
            std::stoi(s.body().findObject("mg")->findData("lastIterations")->valueText());
    }
    EXPECT_EQ(s.log(), "");
    return s.body().get<MechanicalState<Vec3Types>>()->readCoord(VecId::position());
  };
  const std::vector<Vec3d> ldl = run("<SparseLDLSolver/>", nullptr);
  const std::string fcg =
      "<MultigridLinearSolver name=\"mg\" levels=\"2\" conjugateGradient=\"true\" "
      "iterations=\"50\" tolerance=\"1e-10\" ";
  int fresh = 0, stale = 0, staleWarm = 0, everyFive = 0, assembledEveryThree = 0;
  const std::vector<Vec3d> a = run(fcg + "/>", &fresh);
  const std::vector<Vec3d> b = run(fcg + "coarseUpdateInterval=\"0\"/>", &stale);
  const std::vector<Vec3d> c =
      run(fcg + "coarseUpdateInterval=\"0\" warmStart=\"true\"/>", &staleWarm);
  const std::vector<Vec3d> d =
      run(fcg + "coarseUpdateInterval=\"5\" warmStart=\"true\"/>", &everyFive);
  // The system assembled every third solve only (the outer CG multiplies through the force
  // fields in between), the cycles' matrices in single precision.
  const std::vector<Vec3d> e = run(
      fcg + "fineUpdateInterval=\"3\" matrixPrecision=\"single\"/>",
      &assembledEveryThree);
  std::printf(
      "flexible CG iterations over 20 steps: fresh %d, stale %d, stale + warm %d, "
      "every 5 + warm %d, assembled every 3 (single) %d\n",
      fresh, stale, staleWarm, everyFive, assembledEveryThree);
  double tipDrop = 0;
  for (const Vec3d& p : ldl) tipDrop = std::max(tipDrop, -p.y());
  EXPECT_GT(tipDrop, 1e-3);  // the beam bent (and rotated its elements)
  for (const std::vector<Vec3d>* x : {&a, &b, &c, &d, &e}) {
    ASSERT_EQ(x->size(), ldl.size());
    double difference = 0;
    for (std::size_t i = 0; i < ldl.size(); ++i)
      difference = std::max(difference, ((*x)[i] - ldl[i]).norm());
    EXPECT_LT(difference, 1e-7 * (1 + tipDrop));
  }
  // The stale coarse levels cost iterations, but few; starting from the last step's solution
  // saves some.
  EXPECT_LE(stale, 2 * fresh);
  EXPECT_LT(staleWarm, stale);
  EXPECT_LE(assembledEveryThree, 2 * fresh);
}

// StaticSolver (one Newton step, linear elements) lands where SparseLDL does; a solve that
// misses the tolerance warns once, on the field to raise.
TEST(MultigridLinearSolver, StaticSolverStepAndTheWarningWhenNotConverged) {
  auto solve = [](const std::string& solver) {
    LoadedScene s(cantileverScene(
        Vec3i(8, 4, 4), 2.0, 40000, 0.3,
        "<StaticSolver newton_iterations=\"1\" maxNbIterationsLineSearch=\"1\"/>" + solver));
    EXPECT_TRUE(s.loaded) << s.log();
    EXPECT_TRUE(s.scene->step()) << s.log();
    EXPECT_TRUE(s.scene->step()) << s.log();
    std::vector<Vec3d> x = s.body().get<MechanicalState<Vec3Types>>()->readCoord(VecId::position());
    int warnings = 0;
    for (const Message& m : s.scene->log().messages())
      warnings += m.level == MessageLevel::warning && m.field == "iterations";
    return std::make_pair(x, warnings);
  };
  const auto [ldl, ldlWarnings] = solve("<SparseLDLSolver/>");
  const auto [mg, mgWarnings] = solve(
      "<MultigridLinearSolver levels=\"2\" conjugateGradient=\"true\" iterations=\"60\" "
      "tolerance=\"1e-12\"/>");
  const int shortWarnings =
      solve("<MultigridLinearSolver levels=\"2\" iterations=\"1\" tolerance=\"1e-12\"/>").second;
  EXPECT_EQ(mgWarnings, 0);
  EXPECT_EQ(shortWarnings, 1);  // once, though both solves missed it
  double difference = 0, drop = 0;
  for (std::size_t i = 0; i < ldl.size(); ++i) {
    difference = std::max(difference, (ldl[i] - mg[i]).norm());
    drop = std::max(drop, -ldl[i].y());
  }
  EXPECT_GT(drop, 1e-3);
  EXPECT_LT(difference, 1e-8 * drop);
}

TEST(MultigridLinearSolver, ReportsAMissingGrid) {
  LoadedScene s(
      "<Node name=\"root\"><Node name=\"Body\"><StaticSolver/>"
      "<MultigridLinearSolver name=\"mg\"/><MechanicalObject position=\"0 0 0  1 0 0\"/>"
      "<UniformMass/></Node></Node>");
  EXPECT_FALSE(s.loaded);
  EXPECT_TRUE(s.reported(MessageLevel::error, "topology", "no grid found")) << s.log();
}

TEST(MultigridLinearSolver, RefusesNegativeLevels) {
  LoadedScene s(cantileverScene(Vec3i(4, 2, 2), 2.0, 40000, 0.3,
                                "<StaticSolver/><MultigridLinearSolver levels=\"-1\"/>"));
  EXPECT_FALSE(s.loaded);
  bool named = false;
  for (const Message& m : s.scene->log().messages())
    named |= m.level == MessageLevel::error && m.field == "levels";
  EXPECT_TRUE(named) << s.log();
}

// Per-level counts must not be negative; assembling every N solves needs the outer CG (the
// stationary cycles take their residuals from the assembled matrix): a warning, then the
// system is assembled at every solve and the solve is right.
TEST(MultigridLinearSolver, ReportsBadPerLevelCountsAndAnIntervalWithoutConjugateGradient) {
  {
    LoadedScene s(cantileverScene(
        Vec3i(4, 2, 2), 2.0, 40000, 0.3,
        "<StaticSolver/><MultigridLinearSolver levels=\"1\" levelSmoothing=\"2 -1\"/>"));
    EXPECT_FALSE(s.loaded);
    bool named = false;
    for (const Message& m : s.scene->log().messages())
      named |= m.level == MessageLevel::error && m.field == "levelSmoothing";
    EXPECT_TRUE(named) << s.log();
  }
  LoadedScene s(cantileverScene(Vec3i(4, 2, 2), 2.0, 40000, 0.3,
                                "<StaticSolver/><MultigridLinearSolver name=\"mg\" "
                                "levels=\"1\" fineUpdateInterval=\"3\" iterations=\"50\" "
                                "tolerance=\"1e-10\"/>"));
  ASSERT_TRUE(s.loaded) << s.log();
  bool warned = false;
  for (const Message& m : s.scene->log().messages())
    warned |= m.level == MessageLevel::warning && m.field == "fineUpdateInterval";
  EXPECT_TRUE(warned) << s.log();
  EXPECT_TRUE(s.scene->step()) << s.log();
  EXPECT_LE(std::stod(s.body().findObject("mg")->findData("lastResidual")->valueText()), 1e-10);
}

TEST(MultigridLinearSolver, ReportsAStateThatDoesNotMatchTheGrid) {
  // The solver is linked to a grid of 3 x 3 x 3 points; the beam has 5 x 3 x 3.
  std::string xml = cantileverScene(
      Vec3i(4, 2, 2), 2.0, 40000, 0.3,
      "<StaticSolver/><MultigridLinearSolver name=\"mg\" topology=\"@../Other/grid\"/>");
  xml.insert(xml.rfind("</Node>"),
             "<Node name=\"Other\"><RegularGridTopology name=\"grid\" n=\"3 3 3\"/></Node>");
  LoadedScene s(xml);
  ASSERT_TRUE(s.loaded) << s.log();
  s.scene->step();
  EXPECT_TRUE(s.reported(MessageLevel::error, "topology", "has 27 points")) << s.log();
  for (const Vec3d& p : s.body().get<MechanicalState<Vec3Types>>()->readCoord(VecId::position()))
    EXPECT_TRUE(p.allFinite());
}

TEST(MultigridLinearSolver, ReportsHexahedraOffALattice) {
  // Two hexahedra, the second one's corner moved: not a lattice cell.
  LoadedScene s(
      "<Node name=\"root\" gravity=\"0 -10 0\"><Node name=\"Body\"><StaticSolver/>"
      "<MultigridLinearSolver name=\"mg\" levels=\"1\"/>"
      "<MeshTopology name=\"mesh\" position=\"0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  "
      "0 1 1  2 0 0  2 1 0  2 0 1  2.3 1 1\" hexahedra=\"0 1 2 3 4 5 6 7  1 8 9 2 5 10 11 6\"/>"
      "<MechanicalObject name=\"dofs\" position=\"@mesh.position\"/><UniformMass/>"
      "<FixedProjectiveConstraint indices=\"0 3 4 7\"/>"
      "<HexahedronFEMForceField youngModulus=\"100\" poissonRatio=\"0.3\"/></Node></Node>");
  ASSERT_TRUE(s.loaded) << s.log();
  s.scene->step();
  EXPECT_TRUE(s.reported(MessageLevel::error, "topology", "not a cell of the axis-aligned"))
      << s.log();
}

}  // namespace
}  // namespace stroma::test
