// SPDX-License-Identifier: MIT
// CGLinearSolver: the matrix-free and assembled variants take the same implicit steps, and the
// Jacobi preconditioner (assembled only) solves a badly scaled diagonal system in one
// iteration.
#include <gtest/gtest.h>

#include "DirectSolve.h"
#include "LatticeScene.h"

namespace stroma::test {
namespace {

const std::string kCG = R"(iterations="5000" tolerance="1e-14" threshold="1e-300")";

TEST(CGLinearSolver, MatrixFreeAndAssembledTakeTheSameSteps) {
  const std::string ode = R"(<EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.1"/>)";
  SolverScene matrixFree(latticeScene(5, ode + "<CGLinearSolver " + kCG + "/>"));
  SolverScene assembled(latticeScene(
      5, ode + R"(<CGLinearSolver template="CompressedRowSparseMatrixMat3x3d" )" + kCG + "/>"));
  ASSERT_TRUE(matrixFree.loaded()) << matrixFree.log();
  ASSERT_TRUE(assembled.loaded()) << assembled.log();
  for (int n = 0; n < 10; ++n) {
    ASSERT_TRUE(matrixFree.step()) << matrixFree.log();
    ASSERT_TRUE(assembled.step()) << assembled.log();
  }
  double difference = 0, displacement = 0;
  const auto& rest = matrixFree.state().readCoord(VecId::restPosition());
  for (std::size_t i = 0; i < rest.size(); ++i) {
    difference = std::max(difference, (matrixFree.position(i) - assembled.position(i)).norm());
    displacement = std::max(displacement, (matrixFree.position(i) - rest[i]).norm());
  }
  EXPECT_GT(displacement, 1e-3);  // the lattice moved (gravity, springs)
  EXPECT_LT(difference, 1e-10 * displacement);
}

// Three axes of very different stiffness: A = M - h^2 K is diagonal with three distinct values
// spread over 4 orders of magnitude. Plain CG needs one iteration per distinct eigenvalue;
// Jacobi-preconditioned CG sees the identity.
std::string scaledScene(const std::string& cg) {
  std::string xml = oscillatorScene("<EulerImplicitSolver/>" + cg, 1.0, 1.0, "1 1 1  2 -1 0.5",
                                    "0 0 0  0 0 0", 0.01);
  const std::string isotropic = "stiffness=\"1 1 1\"";
  return xml.replace(xml.find(isotropic), isotropic.size(), "stiffness=\"1 1e4 1e8\"");
}

TEST(CGLinearSolver, JacobiPreconditionerSolvesADiagonalSystemInOneIteration) {
  const std::string assembled = R"(template="CompressedRowSparseMatrixd" )" + kCG;
  SolverScene plain(scaledScene("<CGLinearSolver name=\"cg\" " + assembled + "/>"));
  SolverScene jacobi(
      scaledScene("<CGLinearSolver name=\"cg\" jacobiPreconditioner=\"true\" " + assembled + "/>"));
  ASSERT_TRUE(plain.loaded()) << plain.log();
  ASSERT_TRUE(jacobi.loaded()) << jacobi.log();
  ASSERT_TRUE(plain.step()) << plain.log();
  ASSERT_TRUE(jacobi.step()) << jacobi.log();
  EXPECT_GE(std::stoi(plain.field("cg", "lastIterations")), 3);
  EXPECT_EQ(jacobi.field("cg", "lastIterations"), "1");
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_LT((plain.position(i) - jacobi.position(i)).norm(), 1e-12);
  // Backward Euler on each axis: x1 = x0 / (1 + k h^2).
  EXPECT_NEAR(jacobi.position(1).z(), 0.5 / (1 + 1e8 * 1e-4), 1e-15);
}

TEST(CGLinearSolver, WarnsThatJacobiNeedsAnAssembledTemplate) {
  SolverScene s(scaledScene(R"(<CGLinearSolver jacobiPreconditioner="true"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  bool warned = false;
  for (const Message& m : s.scene().log().messages())
    warned |= m.level == MessageLevel::warning && m.field == "jacobiPreconditioner" &&
              m.text.find("GraphScattered") != std::string::npos;
  EXPECT_TRUE(warned) << s.log();
}

TEST(CGLinearSolver, AcceptsSofasFormerFieldNames) {
  // oneTetrahedron.scn: maxIter and smallDenominatorThreshold for iterations and threshold.
  SolverScene s(scaledScene(R"(<CGLinearSolver name="cg" template="CompressedRowSparseMatrixd"
      maxIter="2" tolerance="1e-14" smallDenominatorThreshold="1e-30"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("cg", "iterations"), "2");
  EXPECT_EQ(s.field("cg", "threshold"), "1e-30");
  EXPECT_EQ(s.field("cg", "lastIterations"), "2");  // stopped by maxIter, unconverged
}

TEST(CGLinearSolver, AcceptsTheUnsuffixedSofaTemplates) {
  for (const std::string t : {"CompressedRowSparseMatrix", "CompressedRowSparseMatrixMat3x3"}) {
    SolverScene s(
        scaledScene("<CGLinearSolver name=\"cg\" jacobiPreconditioner=\"true\" "
                    "template=\"" +
                    t + "\" " + kCG + "/>"));
    ASSERT_TRUE(s.loaded()) << s.log();
    ASSERT_TRUE(s.step()) << s.log();
    EXPECT_EQ(s.field("cg", "lastIterations"), "1") << t;  // assembled: Jacobi applies
    EXPECT_EQ(s.scene().log().count(MessageLevel::warning), 0u) << s.log();
  }
}

// CG that stops short says so once, with the residual it reached and why it stopped; the
// number of unconverged solves is summed up when the scene ends. (Whether the stop is a
// divergence is the ODE solver's own warning, maxLinearResidual: not counted here.)
std::vector<Message> warningsOf(const MessageLog& log) {
  std::vector<Message> warnings;
  for (const Message& m : log.messages())
    if (m.level == MessageLevel::warning && m.componentClass == "CGLinearSolver")
      warnings.push_back(m);
  return warnings;
}

TEST(CGLinearSolver, SaysOnceThatItStoppedAtTheIterationLimit) {
  std::vector<Message> warnings;
  {
    SolverScene s(scaledScene(R"(<CGLinearSolver name="cg" iterations="2" tolerance="1e-14"
        threshold="1e-300"/>)"));
    ASSERT_TRUE(s.loaded()) << s.log();
    for (int n = 0; n < 3; ++n) ASSERT_TRUE(s.step()) << s.log();
    warnings = warningsOf(s.scene().log());
    ASSERT_EQ(warnings.size(), 1u) << s.log();
  }
  const Message& m = warnings.front();
  EXPECT_EQ(m.field, "iterations");
  EXPECT_NE(m.text.find("CG stopped after 2 iterations without converging: relative residual "),
            std::string::npos)
      << m.text;
  EXPECT_NE(m.text.find("> tolerance 1e-14 (raise iterations"), std::string::npos) << m.text;
}

TEST(CGLinearSolver, SaysWhenTheDenominatorFallsBelowTheThreshold) {
  SolverScene s(scaledScene(R"(<CGLinearSolver name="cg" iterations="100" tolerance="1e-14"
      threshold="1e30"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  const std::vector<Message> warnings = warningsOf(s.scene().log());
  ASSERT_EQ(warnings.size(), 1u) << s.log();
  EXPECT_EQ(warnings.front().field, "threshold");
  EXPECT_NE(warnings.front().text.find("CG stopped after 0 iterations, when p.Ap = "),
            std::string::npos)
      << warnings.front().text;
  EXPECT_NE(warnings.front().text.find("fell below threshold 1e+30, without converging: "
                                       "relative residual 1 > tolerance 1e-14"),
            std::string::npos)
      << warnings.front().text;
}

}  // namespace
}  // namespace stroma::test
