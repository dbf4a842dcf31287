// SPDX-License-Identifier: MIT
// A study of `stroma bench` (issue 7 item 3): a scene template with ${name} placeholders and
// axes of named substitutions (model, resolution, dt, solver) whose product is run row by row.
// The file format is documented in bench/studies/README.md.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stroma::cli {

/// One value of an axis: its name (the CSV cell) and the placeholders it sets.
struct StudyValue {
  std::string name;
  std::map<std::string, std::string> substitutions;  ///< placeholder -> text
  bool quick = true;                                 ///< part of the --quick version
  /// Overrides the study's step count (the smallest of a combination's values wins).
  std::optional<long long> steps;
  std::optional<long long> quickSteps;  ///< ... in the --quick version
  int line = 0;
};

struct StudyAxis {
  std::string name;  ///< one of kStudyAxes
  std::vector<StudyValue> values;
};

/// A condition on a combination: axis name -> value name; a combination matches when every
/// named axis has that value ("*" at the end of a value name matches any suffix).
struct StudyFilter {
  std::map<std::string, std::string> values;
  std::string reason;  ///< why (Skip) or what is expected (Expect)
  int line = 0;
};

/// A number read from a component of the loaded scene after the run: the component by class
/// name or by object name, its Data by name, multiplied by `scale`.
struct StudyColumn {
  std::string column;  ///< CSV column
  std::string component;
  std::string data;
  double scale = 1;
};

/// The axes a study may have, in the order of the CSV columns.
inline const std::vector<std::string> kStudyAxes = {"model", "resolution", "solver", "dt"};

struct Study {
  std::filesystem::path file;       ///< the study file
  std::string name;                 ///< its stem: STUDY.csv, STUDY.png
  std::string title;                ///< the plot's title
  std::string sceneText;            ///< the template
  std::filesystem::path sceneFile;  ///< where the template came from (anchors relative paths)
  int sceneLine = 0;
  long long steps = 100;
  long long quickSteps = 0;  ///< 0: as steps
  double timeLimit = 120;    ///< seconds of stepping per row before it is stopped
  std::vector<StudyAxis> axes;
  std::map<std::string, std::string> defines;  ///< <Define>: placeholders of every row
  std::vector<StudyColumn> errors;  ///< max_error and rms_error first, then extra columns
  std::string errorLabel;           ///< the plot's y axis (<Error label>)
  std::vector<StudyFilter> skips;
  std::vector<StudyFilter> expectedFailures;
};

/// One row of the product: the chosen value of each axis (kStudyAxes order; an axis the study
/// lacks has no entry).
struct StudyCombination {
  std::map<std::string, const StudyValue*> values;
  long long steps = 0;
  const StudyFilter* expectedFailure = nullptr;
};

/// Reads and checks a study file. On failure returns false with `error` as
/// "FILE:LINE: what is wrong" (malformed XML, unknown axis or element, missing scene, a
/// placeholder no axis defines).
bool readStudy(const std::filesystem::path& file, Study& study, std::string& error);

/// The combinations to run, in file order (the last axis varying fastest), without the
/// skipped ones; with `quick`, only those whose values are all quick.
std::vector<StudyCombination> studyCombinations(const Study& study, bool quick);

/// The scene text of a combination: every ${name} replaced (values may use placeholders too).
/// Returns false with `error` naming the first placeholder left undefined.
bool substituteScene(const Study& study, const StudyCombination& combination, std::string& text,
                     std::string& error);

}  // namespace stroma::cli
