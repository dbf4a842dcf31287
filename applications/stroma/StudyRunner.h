// SPDX-License-Identifier: MIT
// Runs the rows of a study in this process and writes them: STUDY.csv (one row per
// combination, with its status) and STUDY.png (error against wall time, log-log, one curve per
// model, drawn by framework/report/Chart).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "Study.h"

namespace stroma {
class Runtime;
}

namespace stroma::cli {

/// What happened to one row: "ok"; "load-error" (the scene did not load), "diverged" (a step
/// failed, or the errors or positions are not finite), "step-error" (a step failed for another
/// reason), "too-slow" (stopped at the study's timeLimit), "no-error" (the error source is
/// missing from the scene).
struct StudyRow {
  std::map<std::string, std::string> axes;  ///< axis -> value name
  double dt = 0;                            ///< the root's dt, as run
  long long steps = 0;                      ///< steps done
  double wallSeconds = 0;                   ///< time of the steps
  double loadSeconds = 0;                   ///< load and init
  std::vector<double> errors;               ///< study.errors order; NaN when not read
  std::string status = "ok";
  std::string reason;
  bool expected = false;  ///< a failure the study's <Expect> announced

  bool failed() const { return status != "ok"; }
  double stepsPerSecond() const { return wallSeconds > 0 ? double(steps) / wallSeconds : 0; }
};

struct StudyOptions {
  bool quick = false;
  int threads = 1;
  bool verbose = false;  ///< scene warnings to stderr
};

/// Loads, runs and measures one combination; `sceneCopy` (when not empty) receives the scene
/// text as run, so that a user can rerun a row with `stroma run`.
StudyRow runStudyRow(Runtime& runtime, const Study& study, const StudyCombination& combination,
                     const StudyOptions& options, const std::filesystem::path& sceneCopy);

/// Writes the CSV (columns model,resolution,solver,dt,steps,steps_per_s,wall_s,max_error,
/// rms_error, the study's extra columns, then load_s,status,reason). Returns what went wrong,
/// or an empty string.
std::string writeStudyCsv(const std::filesystem::path& file, const Study& study,
                          const std::vector<StudyRow>& rows);

/// Draws max_error against wall_s (log-log) of the rows that ran: one curve per model (per
/// model and solver, or per model and dt, when those axes have several values), points in
/// resolution order. Returns what went wrong (gnuplot missing...), or an empty string.
std::string writeStudyPlot(const std::filesystem::path& file, const Study& study,
                           const std::vector<StudyRow>& rows);

}  // namespace stroma::cli
