// SPDX-License-Identifier: MIT
// CholmodSolver: the same solution as SparseLDLSolver and conjugate gradients in every
// factorization and ordering, one symbolic analysis per sparsity pattern, a clear error for a
// matrix that is not positive definite, SOFA's SparseCholeskySolver name; and the speed of the
// direct solvers on a lattice (printed).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <limits>

#include "plugins/LinearSolver/DirectSolve.h"
#include "plugins/LinearSolver/LatticeScene.h"

namespace stroma::test {
namespace {

const std::string kCG = R"(iterations="5000" tolerance="1e-14" threshold="1e-300")";

TEST(CholmodSolver, GivesTheSameSolutionAsTheOtherSolversInEveryMode) {
  for (const std::string factorization : {"auto", "supernodal", "simplicial"})
    for (const std::string permutation : {"None", "SuiteSparse", "METIS"}) {
      SCOPED_TRACE(factorization + ", " + permutation);
      SolverScene s(latticeScene(
          6,
          "<CholmodSolver name=\"cholmod\" factorization=\"" + factorization + "\" permutation=\"" +
              permutation + "\"/><SparseLDLSolver/><CGLinearSolver " + kCG +
              "/><CGLinearSolver template=\"CompressedRowSparseMatrixd\" " + kCG + "/>",
          0.1, 0.01, 1e5));
      ASSERT_TRUE(s.loaded()) << s.log();
      const Solutions r = solveWithEach(s, implicitEulerMatrix());
      ASSERT_EQ(r.x.size(), 4u);
      EXPECT_TRUE(r.report[0].converged);
      EXPECT_LT(r.residual[0], 1e-12);
      EXPECT_GT(r.x[0].norm(), 0.0);
      for (std::size_t i = 1; i < r.x.size(); ++i)
        EXPECT_LT(relativeDifference(r.x[i], r.x[0]), 1e-10) << "solver " << i;
      if (factorization != "auto") {
        EXPECT_EQ(s.field("cholmod", "supernodalFactor"),
                  factorization == "supernodal" ? "1" : "0");
      }
      EXPECT_EQ(s.scene().log().count(MessageLevel::warning), 0u) << s.log();
    }
}

TEST(CholmodSolver, AnalyzesEachSparsityPatternOnceAndFactorizesEverySolve) {
  SolverScene s(latticeScene(4, R"(<EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.1"/>
    <CholmodSolver name="cholmod"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 10; ++n) ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("cholmod", "symbolicAnalyses"), "1");
  EXPECT_EQ(s.field("cholmod", "factorizations"), "10");
  EXPECT_GT(std::stod(s.field("cholmod", "L_nnz")), 0.0);

  std::string error;
  Base* fixed = s.body().findObject("fixed");
  ASSERT_NE(fixed, nullptr);
  const std::string indices = fixed->findData("indices")->valueText() + " 63";
  ASSERT_TRUE(fixed->findData("indices")->read(indices, error)) << error;
  for (int n = 0; n < 3; ++n) ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("cholmod", "symbolicAnalyses"), "2");
  EXPECT_EQ(s.field("cholmod", "factorizations"), "13");
}

TEST(CholmodSolver, ReportsAMatrixThatIsNotPositiveDefinite) {
  for (const std::string factorization : {"supernodal", "simplicial"}) {
    SCOPED_TRACE(factorization);
    // The anchor of point 1 pulls the wrong way along y: M - h^2 K has one negative pivot.
    SolverScene s(oscillatorScene(
        "<EulerImplicitSolver/><CholmodSolver factorization=\"" + factorization + "\"/>", -1e4, 1.0,
        "1 0 0", "0 0 0", 0.1));
    ASSERT_TRUE(s.loaded()) << s.log();
    EXPECT_FALSE(s.step());
    const Message m = findError(s.scene().log(), "not positive definite");
    EXPECT_NE(m.text.find("point 0, component"), std::string::npos) << s.log();
    EXPECT_NE(m.text.find("of /root/Body/dofs"), std::string::npos) << m.text;
    EXPECT_EQ(m.componentClass, "CholmodSolver");
    EXPECT_EQ(s.position(0), Vec3d(1, 0, 0));  // a zero correction, not garbage
  }
}

TEST(CholmodSolver, AnswersToSofaSparseCholeskySolver) {
  SolverScene s(oscillatorScene(
      R"(<EulerImplicitSolver/><SparseCholeskySolver template="CompressedRowSparseMatrixMat3x3" permutation="METIS"/>)",
      100, 1.0));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_NEAR(s.position(0).x(), 1 / (1 + 100 * 0.01 * 0.01), 1e-14);
  EXPECT_EQ(s.body().get<LinearSolver>()->className(), "CholmodSolver");
}

// Steps per second of implicit Euler on an n^3 lattice with each direct solver (n = 10, or
// STROMA_LATTICE_SIZE); the solvers must also agree on the motion.
TEST(DirectSolvers, StepsPerSecondOnALattice) {
  const char* size = std::getenv("STROMA_LATTICE_SIZE");
  const int n = size ? std::atoi(size) : 10;
  constexpr int kSteps = 10;
  const std::string ode = R"(<EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.1"/>)";
  std::vector<std::vector<Vec3d>> finals;
  for (const std::string solver :
       {R"(<SparseLDLSolver name="direct"/>)", R"(<CholmodSolver name="direct"/>)",
        R"(<CholmodSolver name="direct" factorization="simplicial"/>)",
        R"(<CholmodSolver name="direct" permutation="METIS"/>)"}) {
    SolverScene s(latticeScene(n, ode + solver, 0.1, 0.01, 1e5));
    ASSERT_TRUE(s.loaded()) << s.log();
    ASSERT_TRUE(s.step()) << s.log();  // the symbolic analysis, not timed
    s.scene().timing().clear();
    // Wall time, and the process's CPU time (less sensitive to a loaded machine).
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (int k = 0; k < kSteps; ++k) ASSERT_TRUE(s.step()) << s.log();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    std::printf(
        "[ speed    ] %d^3 lattice, %d unknowns, %-55s L_nnz %-9s %7.2f steps/s "
        "(%.2f per CPU second; linear solve %.0f%%)\n",
        n, 3 * n * n * n, solver.c_str(), s.field("direct", "L_nnz").c_str(), kSteps / seconds,
        kSteps / cpuSeconds, 100 * s.scene().timing().seconds("linearSolve") / seconds);
    finals.push_back(s.state().readCoord(VecId::position()));
  }
  for (std::size_t k = 1; k < finals.size(); ++k)
    for (std::size_t i = 0; i < finals[0].size(); ++i)
      ASSERT_LT((finals[k][i] - finals[0][i]).norm(), 1e-10) << "solver " << k << ", point " << i;
}

TEST(CholmodSolver, ReportsANonFiniteMatrixEntryAndWhereItIs) {
  // A hardening anchor: K depends on the position, so a NaN position makes a NaN matrix.
  SolverScene s(oscillatorScene("<EulerImplicitSolver/><CholmodSolver/>", 100.0, 1.0,
                                "1 0 0  0 1 0", "0 0 0  0 0 0", 0.01,
                                R"(<TestAnchorForceField stiffness="0 0 0" cubicStiffness="5"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  s.state().writeCoord(VecId::position())[1].z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(s.step());
  const Message m = findError(s.scene().log(), "NaN or infinite entry");
  EXPECT_NE(m.text.find("at the row of point 1, component 0 of /root/Body/dofs"), std::string::npos)
      << s.log();
  EXPECT_EQ(m.componentClass, "CholmodSolver");
}

}  // namespace
}  // namespace stroma::test
