// SPDX-License-Identifier: MIT
// `stroma check --stability --quick`, run as a user runs it: every case ends with an outcome
// (no crash, no scene of the suite refused), implicit Euler with corotational tetrahedra
// (large and polar) stays bounded on every extreme case, the explicit solvers refuse a time
// step above the stability bound they estimated, and the contact cases (when the build has the
// Collision plugin) end with an outcome for each response and solver.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "support/CliRun.h"

namespace stroma::test {
namespace {

using Row = std::map<std::string, std::string>;

struct SuiteRun {
  CliRun run;
  std::vector<Row> rows;  ///< the CSV's rows, by column name
};

const SuiteRun& quickSuite() {
  static const SuiteRun suite = [] {
    SuiteRun r;
    TempDir dir;
    const auto csv = dir.path() / "stability.csv";
    r.run = runCli(STROMA_CLI, "check --stability --quick --csv \"" + csv.string() + "\"");
    const auto table = readCsv(csv);
    for (std::size_t i = 1; i < table.size(); ++i) {
      Row row;
      for (std::size_t c = 0; c < table[0].size() && c < table[i].size(); ++c)
        row[table[0][c]] = table[i][c];
      r.rows.push_back(row);
    }
    return r;
  }();
  return suite;
}

std::string describe(const Row& row) {
  return row.at("model") + " / " + row.at("solver") + " / " + row.at("case") + " " +
         row.at("value") + ": " + row.at("status") + " " + row.at("reason");
}

TEST(StabilitySuite, EveryCaseEndsWithAnOutcome) {
  const SuiteRun& suite = quickSuite();
  EXPECT_EQ(suite.run.exitCode, 0) << suite.run.output;
  // 7 models x 6 solvers x 9 quick cases, then 2 contact responses x 2 solvers x 4 cases.
  const bool contact = suite.run.output.find("Contact cases left out") == std::string::npos;
  ASSERT_EQ(suite.rows.size(), 7u * 6u * 9u + (contact ? 2u * 2u * 4u : 0u)) << suite.run.output;
  for (const Row& row : suite.rows) {
    const std::string& status = row.at("status");
    EXPECT_TRUE(status == "stable" || status == "stalled" || status == "refused" ||
                status == "diverged")
        << describe(row);
    if (status != "stable") {
      EXPECT_FALSE(row.at("reason").empty()) << describe(row);
    }
  }
}

TEST(StabilitySuite, ImplicitEulerWithCorotationalTetrahedraStaysBounded) {
  int checked = 0;
  for (const Row& row : quickSuite().rows) {
    if (row.at("model").rfind("corotational tetrahedra", 0) != 0 ||
        row.at("solver").rfind("implicit Euler", 0) != 0)
      continue;
    ++checked;
    EXPECT_TRUE(row.at("status") == "stable" || row.at("status") == "stalled") << describe(row);
    const double largest = std::stod(row.at("max_displacement_m"));
    EXPECT_TRUE(std::isfinite(largest)) << describe(row);
  }
  EXPECT_EQ(checked, 2 * 2 * 9);
}

TEST(StabilitySuite, ContactCasesReportTheirPenetration) {
  // Each response with each solver on each case; the penetration is measured whatever the
  // outcome. The constraint response with LDL^T holds every case: nothing goes in, except in the
  // impact, where the box is 5 mm into the floor before the first contact is found (it moves
  // 1 cm a step, the alarm distance is 4 mm; measured 5.03 mm).
  std::map<std::string, int> perResponse;
  for (const Row& row : quickSuite().rows) {
    const std::string& model = row.at("model");
    if (model != "penalty contact" && model != "constraint contact") continue;
    ++perResponse[model + " / " + row.at("solver")];
    const std::string& text = row.at("max_penetration_m");
    const double depth = text.empty() ? NAN : std::stod(text);
    EXPECT_TRUE(std::isfinite(depth) && depth >= 0) << describe(row);
    if (model == "constraint contact" && row.at("solver") == "implicit Euler + LDL") {
      EXPECT_EQ(row.at("status"), "stable") << describe(row);
      EXPECT_LT(depth, row.at("case") == "impact 10 m/s" ? 6e-3 : 1e-4) << describe(row);
    }
  }
  if (quickSuite().run.output.find("Contact cases left out") != std::string::npos)
    GTEST_SKIP() << "this build has no Collision plugin";
  for (const char* key :
       {"penalty contact / implicit Euler + CG", "penalty contact / implicit Euler + LDL",
        "constraint contact / implicit Euler + CG", "constraint contact / implicit Euler + LDL"})
    EXPECT_EQ(perResponse[key], 4) << key;
}

TEST(StabilitySuite, ExplicitSolversRefuseATimeStepAboveTheirBound) {
  int above = 0, below = 0;
  for (const Row& row : quickSuite().rows) {
    const std::string& solver = row.at("solver");
    if (solver != "central differences" && solver != "symplectic Euler" && solver != "RK4")
      continue;
    const std::string& bound = row.at("critical_dt_s");
    ASSERT_FALSE(bound.empty()) << describe(row);  // estimated before the run
    const double dt = row.at("case") == "dt" ? std::stod(row.at("value")) : 1e-4;  // baseline
    if (dt > std::stod(bound)) {
      ++above;
      EXPECT_EQ(row.at("status"), "refused") << describe(row);
      EXPECT_NE(row.at("reason").find("is above the stability bound"), std::string::npos)
          << describe(row);
    } else {
      ++below;
    }
  }
  EXPECT_GT(above, 0);
  EXPECT_GT(below, 0);  // dt = 1e-5 s is below the bound of every model
}

TEST(StabilitySuite, SavedScenesRerunWithStromaRun) {
  TempDir dir;
  const CliRun suite =
      runCli(STROMA_CLI, "check --stability --quick --save-scenes \"" + dir.path().string() + "\"");
  ASSERT_EQ(suite.exitCode, 0) << suite.output;
  // Refused in the suite, refused again by stroma run (exit code 1, the bound named).
  const auto refused = dir.path() / "linear-tetrahedra_central-differences_dt-1.scn";
  ASSERT_TRUE(std::filesystem::exists(refused)) << refused;
  const CliRun run = runCli(STROMA_CLI, "run \"" + refused.string() + "\" -n 5");
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find("divergence (time step above the stability bound) at step 1"),
            std::string::npos)
      << run.output;
  // Stable in the suite: runs to the end.
  const auto stable = dir.path() / "corotational-tetrahedra-polar_implicit-euler-ldl_impact.scn";
  ASSERT_TRUE(std::filesystem::exists(stable)) << stable;
  const CliRun quiet = runCli(STROMA_CLI, "run \"" + stable.string() + "\" -n 5");
  EXPECT_EQ(quiet.exitCode, 0) << quiet.output;
}

}  // namespace
}  // namespace stroma::test
