// SPDX-License-Identifier: MIT
// `stroma bench` (issue 7 item 3): a tiny study of TestCounter scenes run in this process
// through benchCommand, its CSV read back; failing rows and bad study files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "CommandLine.h"
#include "Study.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "support/CliRun.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

using Table = std::vector<std::vector<std::string>>;

std::size_t column(const Table& t, const std::string& name) {
  for (std::size_t i = 0; i < t.front().size(); ++i)
    if (t.front()[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

struct BenchResult {
  int exitCode;
  std::string err;
};

/// benchCommand with StromaTestPlugin on the plugin path; stderr captured.
BenchResult bench(const std::vector<std::string>& args) {
  ::setenv("STROMA_PLUGIN_PATH", testPluginDirectory().c_str(), 1);
  testing::internal::CaptureStderr();
  const int code = cli::benchCommand(args);
  return {code, testing::internal::GetCapturedStderr()};
}

// A TestCounter adds `increment` to `total` at each step and fails at step `fail` (0: never);
// `elapsed` sums the time steps. Model b fails at its second step (its Set overrides the
// Define).
const char* kTinyStudy = R"(<?xml version="1.0"?>
<Study title="tiny" steps="3" quickSteps="2">
  <Scene>
    <Node name="root" dt="${dt}">
      <TestCounter name="counter" increment="${increment}" failAtStep="${fail}" />
      <MechanicalObject name="dofs" position="0 0 0" />
    </Node>
  </Scene>
  <Define name="fail">0</Define>
  <Error component="TestCounter" max="total" rms="elapsed" />
  <Column name="count" component="counter" data="count" />
  <Axis name="model">
    <Value name="a"><Set name="increment">1.5</Set></Value>
    <Value name="b"><Set name="increment">2</Set><Set name="fail">2</Set></Value>
  </Axis>
  <Axis name="dt">
    <Value name="0.1" />
    <Value name="0.5" quick="false" />
  </Axis>
</Study>
)";

/// Runs kTinyStudy, with `from` replaced by `to` when given, and `extra` arguments; the CSV goes
/// to dir/out/tiny.csv.
BenchResult benchTiny(const TempDir& dir, const std::string& from = {}, const std::string& to = {},
                      std::vector<std::string> extra = {}) {
  std::string text = kTinyStudy;
  if (!from.empty()) text.replace(text.find(from), from.size(), to);
  extra.insert(extra.begin(),
               {dir.write("tiny.xml", text).string(), "--output", (dir.path() / "out").string()});
  return bench(extra);
}

TEST(BenchCommand, TinyStudyWritesEveryRowWithItsStatus) {
  TempDir dir;
  const BenchResult r = benchTiny(dir);
  // Model b fails where it was not expected to: the study runs on, then exits with 1.
  EXPECT_EQ(r.exitCode, cli::kSimulationFailure) << r.err;
  EXPECT_NE(r.err.find("2 rows of study tiny failed"), std::string::npos) << r.err;

  const Table t = readCsv(dir.path() / "out/tiny.csv");
  ASSERT_EQ(t.size(), 5u);  // header + 2 x 2
  const std::vector<std::string> expectedHeader = {
      "model",     "resolution", "solver", "dt",     "steps",  "steps_per_s", "wall_s",
      "max_error", "rms_error",  "count",  "load_s", "status", "reason"};
  EXPECT_EQ(t.front(), expectedHeader);
  const std::size_t model = column(t, "model"), dt = column(t, "dt"), steps = column(t, "steps"),
                    maxError = column(t, "max_error"), rmsError = column(t, "rms_error"),
                    count = column(t, "count"), status = column(t, "status"),
                    reason = column(t, "reason"), resolution = column(t, "resolution");
  // Rows in file order, the last axis fastest.
  const char* models[] = {"a", "a", "b", "b"};
  const double dts[] = {0.1, 0.5, 0.1, 0.5};
  for (int i = 0; i < 4; ++i) {
    const auto& row = t[i + 1];
    ASSERT_EQ(row.size(), expectedHeader.size()) << "row " << i;
    EXPECT_EQ(row[model], models[i]);
    EXPECT_EQ(row[resolution], "-");  // no such axis in the study
    EXPECT_DOUBLE_EQ(std::stod(row[dt]), dts[i]);
    if (i < 2) {
      EXPECT_EQ(row[status], "ok");
      EXPECT_EQ(row[steps], "3");
      EXPECT_DOUBLE_EQ(std::stod(row[maxError]), 4.5);           // 3 x 1.5
      EXPECT_NEAR(std::stod(row[rmsError]), 3 * dts[i], 1e-12);  // 3 steps of dt
      EXPECT_EQ(row[count], "3");
    } else {
      EXPECT_EQ(row[status], "step-error");
      EXPECT_EQ(row[steps], "2");
      EXPECT_NE(row[reason].find("step 2"), std::string::npos) << row[reason];
      EXPECT_NE(row[reason].find("failing at step 2"), std::string::npos) << row[reason];
      EXPECT_EQ(row[maxError], "");  // not read from a failed run
    }
  }
}

TEST(BenchCommand, QuickStudyAndExpectedFailures) {
  TempDir dir;
  // Model b's failure announced: the study then succeeds.
  const BenchResult r = benchTiny(
      dir, "</Study>", "<Expect model=\"b\" reason=\"fails on purpose\" /></Study>", {"--quick"});
  EXPECT_EQ(r.exitCode, cli::kSuccess) << r.err;
  const Table t = readCsv(dir.path() / "out/tiny.csv");
  ASSERT_EQ(t.size(), 3u);  // dt 0.5 is not quick
  const std::size_t steps = column(t, "steps"), status = column(t, "status");
  EXPECT_EQ(t[1][steps], "2");  // quickSteps
  EXPECT_EQ(t[1][status], "ok");
  EXPECT_EQ(t[2][status], "step-error (expected)");
}

TEST(BenchCommand, LoadErrorIsARowWithItsReason) {
  TempDir dir;
  // An increment out of TestCounter's range [0, 10]: the scene does not load.
  const BenchResult r =
      benchTiny(dir, "<Set name=\"increment\">2</Set>", "<Set name=\"increment\">20</Set>");
  EXPECT_EQ(r.exitCode, cli::kSimulationFailure) << r.err;
  const Table t = readCsv(dir.path() / "out/tiny.csv");
  ASSERT_EQ(t.size(), 5u);
  const std::size_t status = column(t, "status"), reason = column(t, "reason");
  EXPECT_EQ(t[1][status], "ok");
  EXPECT_EQ(t[3][status], "load-error");
  EXPECT_NE(t[3][reason].find("/root/counter, field 'increment'"), std::string::npos)
      << t[3][reason];
}

TEST(BenchCommand, MissingErrorComponentIsARowStatus) {
  TempDir dir;
  const BenchResult r =
      benchTiny(dir, "component=\"TestCounter\"", "component=\"ReferenceComparison\"");
  EXPECT_EQ(r.exitCode, cli::kSimulationFailure);
  const Table t = readCsv(dir.path() / "out/tiny.csv");
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[1][column(t, "status")], "no-error");
  EXPECT_NE(t[1][column(t, "reason")].find("ReferenceComparison"), std::string::npos);
}

/// A bad study file: exit code 2 and a message "FILE:LINE: ..." containing `what`.
void expectBadStudy(const std::string& text, int line, const std::string& what) {
  TempDir dir;
  const fs::path study = dir.write("bad.xml", text);
  const BenchResult r = bench({study.string(), "--output", (dir.path() / "out").string()});
  EXPECT_EQ(r.exitCode, cli::kBadInput) << r.err;
  EXPECT_NE(r.err.find(study.string() + ":" + std::to_string(line) + ":"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out/bad.csv"));
}

TEST(BenchCommand, BadStudyFilesNameFileAndLine) {
  const std::string scene = "  <Scene><Node name=\"root\" /></Scene>\n";
  expectBadStudy(
      "<Study>\n" + scene + "  <Axis name=\"model\">\n    <Value name=\"a\">\n</Study>\n", 4,
      "malformed XML");
  expectBadStudy(
      "<Study>\n" + scene + "  <Axis name=\"modle\"><Value name=\"a\"/></Axis>\n</Study>\n", 3,
      "unknown axis 'modle' (the axes are model, resolution, solver, dt); did you mean 'model'?");
  expectBadStudy("<Study>\n  <Scene file=\"absent.scn\" />\n</Study>\n", 2,
                 "absent.scn' cannot be read");
  expectBadStudy(
      "<Study>\n  <Scene><Node name=\"${name}\" /></Scene>\n"
      "  <Axis name=\"model\"><Value name=\"a\"/></Axis>\n</Study>\n",
      2, "placeholder ${name} of the scene is defined by no axis value");
  expectBadStudy("<Study steps=\"0\">\n" + scene + "</Study>\n", 1,
                 "'steps' expects an integer >= 1");
  expectBadStudy("<Study>\n" + scene + "  <Axis name=\"model\"><Value name=\"a\"/></Axis>\n" +
                     "  <Skip model=\"b\" />\n</Study>\n",
                 4, "names model 'b', which is not a value of that axis");
  expectBadStudy("<Study>\n" + scene + "  <Scenario />\n</Study>\n", 3,
                 "unknown element <Scenario>");
}

// The quick version of the cantilever study (bench/studies/Cantilever.xml, well under a minute):
// every row runs, and for each model and solver the tip error falls as the mesh is refined
// (10x1x1 -> 20x2x2 cells); the static solver and implicit Euler settle on the same
// equilibrium (to 1 % of the tip deflection).
TEST(BenchCommand, QuickCantileverStudyConverges) {
  TempDir dir;
  const BenchResult r = bench({std::string(STROMA_SOURCE_DIR) + "/bench/studies/Cantilever.xml",
                               "--quick", "--output", dir.path().string()});
  ASSERT_EQ(r.exitCode, cli::kSuccess) << r.err;
  const Table t = readCsv(dir.path() / "Cantilever.csv");
  ASSERT_GT(t.size(), 8u);
  const std::size_t model = column(t, "model"), resolution = column(t, "resolution"),
                    solver = column(t, "solver"), maxError = column(t, "max_error"),
                    status = column(t, "status");
  std::map<std::string, double> error;  // "model/solver/resolution" -> max_error
  for (std::size_t i = 1; i < t.size(); ++i) {
    EXPECT_EQ(t[i][status], "ok") << t[i][model] << " " << t[i][resolution] << " " << t[i][solver];
    error[t[i][model] + "/" + t[i][solver] + "/" + t[i][resolution]] = std::stod(t[i][maxError]);
  }
  int pairs = 0;
  for (const auto& [key, coarse] : error) {
    if (key.find("/10x1x1") == std::string::npos) continue;
    const std::string stem = key.substr(0, key.size() - 6);
    ASSERT_TRUE(error.count(stem + "20x2x2")) << stem;
    EXPECT_LT(error[stem + "20x2x2"], 0.9 * coarse) << stem;
    ++pairs;
    if (stem.find("/static/") != std::string::npos) {
      const std::string dynamic = stem.substr(0, stem.find("/static/")) + "/implicit-cg/";
      for (const char* res : {"10x1x1", "20x2x2"}) {
        ASSERT_TRUE(error.count(dynamic + res)) << dynamic;
        EXPECT_NEAR(error[dynamic + res], error[stem + res], 0.01) << dynamic << res;
      }
    }
  }
  EXPECT_GE(pairs, 4);
}

TEST(BenchCommand, UsageErrors) {
  EXPECT_EQ(bench({}).exitCode, cli::kBadInput);
  EXPECT_EQ(bench({"a.xml", "--fast"}).exitCode, cli::kBadInput);
  const BenchResult missing = bench({"/nonexistent/study.xml"});
  EXPECT_EQ(missing.exitCode, cli::kBadInput);
  EXPECT_NE(missing.err.find("/nonexistent/study.xml: cannot read the study file"),
            std::string::npos)
      << missing.err;
}

}  // namespace
}  // namespace stroma::test
