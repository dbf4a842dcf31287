// SPDX-License-Identifier: MIT
// PCGLinearSolver: preconditioned by a direct solver refreshed every step it takes one
// iteration and the direct solver's steps; refreshed every 5 steps it iterates on the stale
// steps and still takes the same steps; without a preconditioner it is matrix-free CG; SOFA's
// older `preconditioners` name; bad input.
#include <gtest/gtest.h>

#include "DirectSolve.h"
#include "LatticeScene.h"

namespace stroma::test {
namespace {

const std::string kImplicit = R"(<EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.1"/>)";

// Largest distance between the two scenes' points after `steps` steps, relative to the largest
// displacement from rest.
double trajectoryDifference(SolverScene& a, SolverScene& b, int steps) {
  for (int n = 0; n < steps; ++n) {
    EXPECT_TRUE(a.step()) << a.log();
    EXPECT_TRUE(b.step()) << b.log();
  }
  double difference = 0, displacement = 0;
  const auto& rest = a.state().readCoord(VecId::restPosition());
  for (std::size_t i = 0; i < rest.size(); ++i) {
    difference = std::max(difference, (a.position(i) - b.position(i)).norm());
    displacement = std::max(displacement, (a.position(i) - rest[i]).norm());
  }
  EXPECT_GT(displacement, 1e-3);  // the lattice moved
  return difference / displacement;
}

TEST(PCGLinearSolver, WithAnExactPreconditionerTakesOneIterationAndTheDirectSolversSteps) {
  // Springs perturbed by 0.3 m: K changes from step to step.
  SolverScene pcg(latticeScene(4, kImplicit + R"(<PCGLinearSolver name="pcg" preconditioner="@ldl"
      tolerance="1e-20"/> <SparseLDLSolver name="ldl"/>)",
                               0.3, 0.01, 1e4));
  SolverScene ldl(latticeScene(4, kImplicit + "<SparseLDLSolver/>", 0.3, 0.01, 1e4));
  ASSERT_TRUE(pcg.loaded()) << pcg.log();
  ASSERT_TRUE(ldl.loaded()) << ldl.log();
  EXPECT_LT(trajectoryDifference(pcg, ldl, 10), 1e-10);
  EXPECT_EQ(pcg.field("pcg", "lastIterations"), "1");
  EXPECT_EQ(pcg.field("pcg", "refreshes"), "10");
  EXPECT_EQ(pcg.field("ldl", "factorizations"), "10");
  EXPECT_EQ(pcg.scene().log().count(MessageLevel::warning), 0u) << pcg.log();
}

TEST(PCGLinearSolver, RefreshedEveryFiveStepsIteratesOnTheStaleOnesToTheSameSteps) {
  SolverScene pcg(latticeScene(4, kImplicit + R"(<PCGLinearSolver name="pcg" preconditioner="@ldl"
      update_step="5" tolerance="1e-20" iterations="100"/> <SparseLDLSolver name="ldl"/>)",
                               0.3, 0.01, 1e4));
  SolverScene ldl(latticeScene(4, kImplicit + "<SparseLDLSolver/>", 0.3, 0.01, 1e4));
  ASSERT_TRUE(pcg.loaded()) << pcg.log();
  ASSERT_TRUE(ldl.loaded()) << ldl.log();
  SolverScene plain(latticeScene(4, kImplicit + R"(<PCGLinearSolver name="pcg" use_precond="false"
      tolerance="1e-20" iterations="1000"/>)",
                                 0.3, 0.01, 1e4));
  ASSERT_TRUE(plain.loaded()) << plain.log();
  for (int n = 0; n < 4; ++n) ASSERT_TRUE(plain.step()) << plain.log();
  EXPECT_LT(trajectoryDifference(pcg, ldl, 4), 1e-9);
  // Step 4 solves with the factorization of step 1: more than one iteration, but a fraction of
  // plain CG's.
  const int iterations = std::stoi(pcg.field("pcg", "lastIterations"));
  EXPECT_GT(iterations, 1);
  EXPECT_LT(3 * iterations, std::stoi(plain.field("pcg", "lastIterations")));
  EXPECT_LT(trajectoryDifference(pcg, ldl, 6), 1e-9);
  EXPECT_EQ(pcg.field("pcg", "refreshes"), "2");  // solves 1 and 6
  EXPECT_EQ(pcg.field("ldl", "factorizations"), "2");
  EXPECT_EQ(pcg.scene().log().count(MessageLevel::warning), 0u) << pcg.log();
}

TEST(PCGLinearSolver, WithoutPreconditionerIsMatrixFreeConjugateGradients) {
  for (const std::string options : {R"(use_precond="false" preconditioner="@ldl")", ""}) {
    SolverScene pcg(latticeScene(4, kImplicit + R"(<PCGLinearSolver name="pcg" )" + options +
                                        R"( tolerance="1e-28" iterations="1000"/>
        <SparseLDLSolver name="ldl"/>)"));
    SolverScene cg(latticeScene(
        4, kImplicit + R"(<CGLinearSolver iterations="1000" tolerance="1e-14" threshold="1e-300"/>)"));
    ASSERT_TRUE(pcg.loaded()) << pcg.log();
    ASSERT_TRUE(cg.loaded()) << cg.log();
    EXPECT_LT(trajectoryDifference(pcg, cg, 5), 1e-9) << options;
    EXPECT_GT(std::stoi(pcg.field("pcg", "lastIterations")), 5) << options;
    EXPECT_EQ(pcg.field("pcg", "refreshes"), "0") << options;
    EXPECT_EQ(pcg.field("ldl", "factorizations"), "0") << options;
  }
}

TEST(PCGLinearSolver, FindsThePreconditionerBySofasOlderName) {
  SolverScene s(latticeScene(3, kImplicit + R"(<PCGLinearSolver name="pcg" preconditioners="ldl"/>
      <SparseLDLSolver name="ldl"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  ASSERT_TRUE(s.step()) << s.log();
  EXPECT_EQ(s.field("pcg", "lastIterations"), "1");
  EXPECT_EQ(s.field("ldl", "factorizations"), "1");
}

TEST(PCGLinearSolver, SaysOnceThatItStoppedAtTheIterationLimit) {
  SolverScene s(latticeScene(4, kImplicit + R"(<PCGLinearSolver name="pcg" iterations="2"
      tolerance="1e-28"/>)"));
  ASSERT_TRUE(s.loaded()) << s.log();
  for (int n = 0; n < 3; ++n) ASSERT_TRUE(s.step()) << s.log();
  int warnings = 0;
  for (const Message& m : s.scene().log().messages())
    if (m.level == MessageLevel::warning && m.componentClass == "PCGLinearSolver") {
      ++warnings;
      EXPECT_EQ(m.field, "iterations");
      EXPECT_NE(m.text.find("PCG stopped after 2 iterations without converging"),
                std::string::npos)
          << m.text;
    }
  EXPECT_EQ(warnings, 1) << s.log();
}

TEST(PCGLinearSolver, NamesTheFieldOfABadPreconditioner) {
  for (const auto& [solver, field] :
       {std::pair<std::string, std::string>{R"(preconditioners="nothing")", "preconditioners"},
        {R"(name="pcg" preconditioner="@pcg")", "preconditioner"}}) {
    SolverScene s(latticeScene(3, kImplicit + "<PCGLinearSolver " + solver + "/>"));
    bool named = false;
    for (const Message& m : s.scene().log().messages())
      named |= m.level == MessageLevel::error && m.field == field;
    EXPECT_TRUE(named) << s.log();
  }
}

}  // namespace
}  // namespace stroma::test
