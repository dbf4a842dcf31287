// SPDX-License-Identifier: MIT
// `stroma check --stability --quick`, run as a user runs it: every case ends with an outcome
// (no crash, no scene of the suite refused), implicit Euler with corotational tetrahedra
// (large and polar) stays bounded on every extreme case, and the explicit solvers refuse a time
// step above the stability bound they estimated.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {
namespace {

using Row = std::map<std::string, std::string>;

// One CSV line: fields separated by commas, quoted ones with "" for a quote.
std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

struct SuiteRun {
  int code = -1;
  std::string output;
  std::vector<Row> rows;
};

const SuiteRun& quickSuite() {
  static const SuiteRun run = [] {
    SuiteRun r;
    TempDir dir;
    const auto csv = dir.path() / "stability.csv";
    const auto log = dir.path() / "log.txt";
    const std::string command = std::string("\"") + STROMA_CLI +
                                "\" check --stability --quick --csv \"" + csv.string() + "\" > \"" +
                                log.string() + "\" 2>&1";
    const int status = std::system(command.c_str());
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream logFile(log);
    std::stringstream text;
    text << logFile.rdbuf();
    r.output = text.str();
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = splitCsv(line);
    while (std::getline(in, line)) {
      const std::vector<std::string> fields = splitCsv(line);
      Row row;
      for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i)
        row[header[i]] = fields[i];
      r.rows.push_back(row);
    }
    return r;
  }();
  return run;
}

std::string describe(const Row& row) {
  return row.at("model") + " / " + row.at("solver") + " / " + row.at("case") + " " +
         row.at("value") + ": " + row.at("status") + " " + row.at("reason");
}

TEST(StabilitySuite, EveryCaseEndsWithAnOutcome) {
  const SuiteRun& run = quickSuite();
  EXPECT_EQ(run.code, 0) << run.output;
  // 7 models x 6 solvers x 9 quick cases.
  ASSERT_EQ(run.rows.size(), 7u * 6u * 9u) << run.output;
  for (const Row& row : run.rows) {
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

}  // namespace
}  // namespace stroma::test
