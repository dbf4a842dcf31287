// SPDX-License-Identifier: MIT
// `stroma bench STUDY.xml`: every combination of a study run in this process, written as
// DIR/STUDY.csv and DIR/STUDY.png (issue 7 item 3; format in bench/studies/README.md).
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "CommandLine.h"
#include "Study.h"
#include "StudyRunner.h"
#include "core/Runtime.h"

namespace stroma::cli {

int benchCommand(const std::vector<std::string>& args) {
  Arguments a;
  std::string error;
  if (!parseArguments(args, {"--output", "--threads", "--data-path"},
                      {"--quick", "--verbose", "--save-scenes"}, a, error))
    return usageError(error);
  if (a.positional.size() != 1)
    return usageError(a.positional.empty() ? "bench expects a study file"
                                           : "bench expects one study file, got " +
                                                 std::to_string(a.positional.size()));
  long long threads = 1;
  if (!readInteger(a, "--threads", 0, threads, error)) return usageError(error);
  StudyOptions options;
  options.quick = a.has("--quick");
  options.threads = static_cast<int>(threads);
  options.verbose = a.has("--verbose");
  const std::filesystem::path output = a.value("--output") ? *a.value("--output") : "bench-results";

  Study study;
  if (!readStudy(a.positional.front(), study, error)) {
    std::cerr << "stroma: " << error << '\n';
    return kBadInput;
  }
  std::error_code ec;
  std::filesystem::create_directories(output, ec);
  if (ec)
    return usageError("cannot make the output folder '" + output.string() + "': " + ec.message());

  Runtime runtime;
  for (const auto& dir : a.values("--data-path")) runtime.addDataDirectory(dir);
  const std::vector<StudyCombination> combinations = studyCombinations(study, options.quick);
  std::printf("Study %s: %zu rows%s, %d thread%s\n", study.name.c_str(), combinations.size(),
              options.quick ? " (quick)" : "", options.threads, options.threads == 1 ? "" : "s");
  std::vector<StudyRow> rows;
  int unexpected = 0;
  for (const StudyCombination& c : combinations) {
    std::filesystem::path sceneCopy;
    if (a.has("--save-scenes")) {
      sceneCopy =
          output / (study.name + "-scenes") / ("row" + std::to_string(rows.size() + 1) + ".scn");
      std::filesystem::create_directories(sceneCopy.parent_path(), ec);
    }
    rows.push_back(runStudyRow(runtime, study, c, options, sceneCopy));
    const StudyRow& r = rows.back();
    std::string label;
    for (const auto& axis : kStudyAxes)
      if (auto it = r.axes.find(axis); it != r.axes.end()) label += " " + axis + "=" + it->second;
    std::printf("  %-60s %6lld steps %9.4f s %10.1f steps/s", label.c_str(), r.steps, r.wallSeconds,
                r.stepsPerSecond());
    if (!r.errors.empty() && !r.failed()) std::printf("  max_error %.4g", r.errors.front());
    if (r.failed())
      std::printf("  %s%s: %s", r.status.c_str(), r.expected ? " (expected)" : "",
                  r.reason.c_str());
    std::printf("\n");
    std::fflush(stdout);
    if (r.failed() && !r.expected) ++unexpected;
  }

  const std::filesystem::path csv = output / (study.name + ".csv");
  const std::filesystem::path png = output / (study.name + ".png");
  if (std::string what = writeStudyCsv(csv, study, rows); !what.empty()) {
    std::cerr << "stroma: " << what << '\n';
    return kSimulationFailure;
  }
  std::printf("Wrote %s\n", csv.string().c_str());
  if (std::string what = writeStudyPlot(png, study, rows); !what.empty())
    std::cerr << "stroma: warning: " << what << '\n';
  else
    std::printf("Wrote %s\n", png.string().c_str());
  if (unexpected) {
    std::cerr << "stroma: " << unexpected << (unexpected == 1 ? " row" : " rows") << " of study "
              << study.name << " failed (see the status column of " << csv.string() << ")\n";
    return kSimulationFailure;
  }
  return kSuccess;
}

}  // namespace stroma::cli
