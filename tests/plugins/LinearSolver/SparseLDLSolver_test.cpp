// SPDX-License-Identifier: MIT
// SparseLDLSolver: the same solution as conjugate gradients (matrix-free and assembled) on a
// 3D spring lattice, one symbolic analysis per sparsity pattern, a clear error for a matrix
// that is singular or indefinite, and SOFA's names and templates (AsyncSparseLDLSolver solves
// synchronously).
#include <gtest/gtest.h>

#include <limits>

#include "DirectSolve.h"
#include "LatticeScene.h"

namespace stroma::test {
namespace {

const std::string kCG = R"(iterations="5000" tolerance="1e-14" threshold="1e-300")";

TEST(SparseLDLSolver, GivesTheSameSolutionAsConjugateGradients) {
  SolverScene s(latticeScene(6,
                             R"(<SparseLDLSolver/>
    <CGLinearSolver )" + kCG + R"(/>
    <CGLinearSolver template="CompressedRowSparseMatrixMat3x3d" )" +
                                 kCG + "/>",
                             0.1, 0.01, 1e5));
  ASSERT_TRUE(s.loaded()) << s.log();
  const Solutions r = solveWithEach(s, implicitEulerMatrix());
  ASSERT_EQ(r.x.size(), 3u);
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    EXPECT_LT(r.residual[i], 1e-12) << "solver " << i;
    EXPECT_TRUE(r.report[i].converged) << "solver " << i;
  }
  EXPECT_GT(r.x[0].norm(), 0.0);
  EXPECT_LT(relativeDifference(r.x[1], r.x[0]), 1e-10);  // matrix-free CG
  EXPECT_LT(relativeDifference(r.x[2], r.x[0]), 1e-10);  // assembled CG
  EXPECT_EQ(s.scene().log().count(MessageLevel::warning), 0u) << s.log();
}

TEST(SparseLDLSolver, AnalyzesEachSparsityPatternOnceAndFactorizesEverySolve) {
  SolverScene s(latticeScene(4, R"(<EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.1"/>
    <SparseLDLSolver name="ldl"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 10; ++n) ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("ldl", "symbolicAnalyses"), "1");
  EXPECT_EQ(s.field("ldl", "factorizations"), "10");
  EXPECT_GT(std::stoi(s.field("ldl", "L_nnz")), 0);

  // Fixing one more point removes entries from the matrix: a new pattern, a new analysis.
  std::string error;
  Base* fixed = s.body().findObject("fixed");
  ASSERT_NE(fixed, nullptr);
  const std::string indices = fixed->findData("indices")->valueText() + " 63";
  ASSERT_TRUE(fixed->findData("indices")->read(indices, error)) << error;
  for (int n = 0; n < 3; ++n) ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("ldl", "symbolicAnalyses"), "2");
  EXPECT_EQ(s.field("ldl", "factorizations"), "13");
}

TEST(SparseLDLSolver, SolvesAnIndefiniteSystemAndWarnsOnce) {
  // An anchor of negative stiffness: M - h^2 K = 1 - 0.01 * 1e4 = -99 on every row. LDL^T
  // solves the indefinite system exactly (backward Euler from x = 1 at rest gives
  // x1 = 1 / (1 + k h^2) = -1/99), and says once that the matrix is indefinite.
  SolverScene s(oscillatorScene("<EulerImplicitSolver/><SparseLDLSolver/>", -1e4, 1.0, "1 0 0",
                                "0 0 0", 0.1));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_NEAR(s.position(0).x(), -1.0 / 99.0, 1e-14);
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.scene().log().errorCount(), 0u) << s.log();
  std::size_t warnings = 0;
  for (const Message& m : s.scene().log().messages()) {
    if (m.level != MessageLevel::warning) continue;
    ++warnings;
    EXPECT_NE(m.text.find("indefinite (pivot D = -99"), std::string::npos) << m.text;
    EXPECT_NE(m.text.find("point 0, component"), std::string::npos) << m.text;
    EXPECT_NE(m.text.find("of /root/Body/dofs"), std::string::npos) << m.text;
    EXPECT_EQ(m.componentClass, "SparseLDLSolver");
  }
  EXPECT_EQ(warnings, 1u) << s.log();
}

TEST(SparseLDLSolver, ReportsASingularStaticSystem) {
  // Nothing holds the point along x: -K has a zero row.
  const std::string xml = R"(<Node name="root" dt="1" gravity="0 0 0">
  <Node name="Body">
    <StaticSolver/>
    <SparseLDLSolver/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <TestAnchorForceField stiffness="5 0 5"/>
    <ConstantForceField force="1 1 1"/>
  </Node>
</Node>)";
  SolverScene s(xml);
  ASSERT_TRUE(s.loaded()) << s.log();
  EXPECT_FALSE(s.step());
  const Message m = findError(s.scene().log(), "singular");
  EXPECT_NE(m.text.find("pivot D = 0 at point"), std::string::npos) << s.log();
  EXPECT_NE(m.text.find("component 1 of /root/Body/dofs"), std::string::npos) << m.text;
}

TEST(SparseLDLSolver, AcceptsSofaNamesAndTemplates) {
  for (const std::string component :
       {R"(<EigenSimplicialLDLT template="CompressedRowSparseMatrixMat3x3"/>)",
        R"(<EigenSimplicialLDLT template="CompressedRowSparseMatrixd"/>)",
        R"(<EigenSimplicialLLT template="CompressedRowSparseMatrixMat3x3d"/>)",
        R"(<SparseLDLSolver template="CompressedRowSparseMatrix" parallelInverseProduct="true"/>)",
        R"(<SparseLDLSolver template="CompressedRowSparseMatrixMat3x3f"/>)"}) {
    SCOPED_TRACE(component);
    SolverScene s(oscillatorScene("<EulerImplicitSolver/>" + component, 100, 1.0));
    ASSERT_TRUE(s.loaded()) << s.log();
    ASSERT_TRUE(s.step()) << s.log();
    // Backward Euler from x = 1 at rest: x1 = 1 / (1 + k h^2).
    EXPECT_NEAR(s.position(0).x(), 1 / (1 + 100 * 0.01 * 0.01), 1e-14);
    EXPECT_EQ(s.body().get<LinearSolver>()->className(), "SparseLDLSolver");
  }
}

// SOFA's AsyncSparseLDLSolver factorizes in a thread and solves with a factorization a step late;
// Stroma's alias factorizes every solve synchronously: the same states as SparseLDLSolver on a
// perturbed spring lattice (a matrix that changes as the springs turn), one factorization a step.
TEST(SparseLDLSolver, AsyncSparseLDLSolverFactorizesSynchronously) {
  auto run = [](const std::string& solver) {
    SolverScene s(latticeScene(
        4, R"(<EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.1"/>)" + solver));
    EXPECT_TRUE(s.loaded()) << s.log();
    for (int n = 0; n < 8; ++n) EXPECT_TRUE(s.step()) << s.log();
    EXPECT_EQ(s.field("ldl", "factorizations"), "8");
    EXPECT_EQ(s.body().get<LinearSolver>()->className(), "SparseLDLSolver");
    const auto& x = s.state().readCoord(VecId::position());
    return std::vector<Vec3d>(x.begin(), x.end());
  };
  const std::vector<Vec3d> async =
      run(R"(<AsyncSparseLDLSolver name="ldl" template="CompressedRowSparseMatrixMat3x3"/>)");
  const std::vector<Vec3d> sync = run(R"(<SparseLDLSolver name="ldl"/>)");
  ASSERT_EQ(async.size(), sync.size());
  for (std::size_t i = 0; i < sync.size(); ++i) EXPECT_EQ(async[i], sync[i]) << "point " << i;
}

TEST(SparseLDLSolver, ReportsANonFiniteMatrixEntryAndWhereItIs) {
  // A hardening anchor: K depends on the position, so a NaN position makes a NaN matrix.
  SolverScene s(oscillatorScene("<EulerImplicitSolver/><SparseLDLSolver/>", 100.0, 1.0,
                                "1 0 0  0 1 0", "0 0 0  0 0 0", 0.01,
                                R"(<TestAnchorForceField stiffness="0 0 0" cubicStiffness="5"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  s.state().writeCoord(VecId::position())[1].z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(s.step());
  const Message m = findError(s.scene().log(), "NaN or infinite entry");
  EXPECT_NE(m.text.find("at the row of point 1, component 0 of /root/Body/dofs"), std::string::npos)
      << s.log();
  EXPECT_EQ(m.componentClass, "SparseLDLSolver");
}

}  // namespace
}  // namespace stroma::test
