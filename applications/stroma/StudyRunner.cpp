// SPDX-License-Identifier: MIT
#include "StudyRunner.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>

#include "core/BaseState.h"
#include "core/Runtime.h"
#include "report/Chart.h"
#include "simulation/Scene.h"

namespace stroma::cli {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The first object of the graph, depth first, whose class name or object name is `name`.
Base* findComponent(const Node& node, const std::string& name) {
  for (const auto& object : node.objects())
    if (object->className() == name || object->name() == name) return object.get();
  for (const auto& child : node.children())
    if (Base* found = findComponent(*child, name)) return found;
  return nullptr;
}

/// False when some state of the graph holds a position that is not finite.
bool positionsFinite(const Node& node) {
  std::vector<double> values;
  for (const auto& object : node.objects())
    if (const auto* state = dynamic_cast<const BaseState*>(object.get())) {
      state->copyPositions(values);
      for (double v : values)
        if (!std::isfinite(v)) return false;
    }
  for (const auto& child : node.children())
    if (!positionsFinite(*child)) return false;
  return true;
}

/// The first error of the log, formatted as the console prints it, without the file prefix.
std::string firstError(const MessageLog& log) {
  for (const Message& m : log.messages())
    if (m.level == MessageLevel::error) {
      std::string where = m.componentPath;
      if (!m.field.empty()) where += (where.empty() ? "field '" : ", field '") + m.field + "'";
      return where.empty() ? m.text : where + ": " + m.text;
    }
  return "no error message";
}

bool soundsDivergent(const std::string& text) {
  for (const char* word : {"NaN", "nan", "Inf", "inf", "diverg", "not finite"})
    if (text.find(word) != std::string::npos) return true;
  return false;
}

/// Reads a Data as one number: "1.5" or the first value of a list.
double readNumber(const Base& component, const std::string& dataName, std::string& error) {
  const BaseData* data = component.findData(dataName);
  if (!data) {
    error = component.className() + " '" + component.name() + "' has no Data '" + dataName + "'";
    return kNaN;
  }
  const std::string text = data->valueText();
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str()) {
    error = component.className() + "." + dataName + " is not a number ('" + text + "')";
    return kNaN;
  }
  return value;
}

/// CSV cell: quoted when it holds a comma, a quote or a line break.
std::string csvCell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text)
    out += c == '"' ? std::string("\"\"") : c == '\n' ? std::string(" ") : std::string(1, c);
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream out;
  out << std::setprecision(6) << v;
  return out.str();
}

}  // namespace

StudyRow runStudyRow(Runtime& runtime, const Study& study, const StudyCombination& combination,
                     const StudyOptions& options, const std::filesystem::path& sceneCopy) {
  StudyRow row;
  for (const auto& [axis, value] : combination.values) row.axes[axis] = value->name;
  row.errors.assign(study.errors.size(), kNaN);
  row.expected = combination.expectedFailure != nullptr;

  std::string text, error;
  if (!substituteScene(study, combination, text, error)) {
    row.status = "load-error";
    row.reason = error;
    return row;
  }
  if (!sceneCopy.empty()) std::ofstream(sceneCopy) << text;
  Scene scene(runtime);
  scene.setThreadCount(options.threads);
  if (options.verbose)
    scene.log().addSink(std::make_shared<StreamSink>(std::cerr, MessageLevel::warning));
  const auto loadStart = std::chrono::steady_clock::now();
  if (!scene.loadString(text, study.sceneFile)) {
    row.status = "load-error";
    row.reason = firstError(scene.log());
    return row;
  }
  row.loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - loadStart).count();
  row.dt = scene.root().dt();

  // The steps, timed as `stroma run` times them (the scene's "step" phase).
  const double before = scene.timing().seconds("step");
  for (long long i = 0; i < combination.steps; ++i) {
    const bool ok = scene.step();
    ++row.steps;
    if (!ok) {
      row.reason = "step " + std::to_string(row.steps) + ": " + firstError(scene.log());
      row.status = soundsDivergent(row.reason) ? "diverged" : "step-error";
      break;
    }
    if (scene.timing().seconds("step") - before > study.timeLimit && i + 1 < combination.steps) {
      row.status = "too-slow";
      row.reason = "stopped after " + std::to_string(row.steps) +
                   " steps at the study's timeLimit " + number(study.timeLimit) + " s";
      break;
    }
  }
  row.wallSeconds = scene.timing().seconds("step") - before;
  if (row.failed()) return row;
  if (!positionsFinite(scene.root())) {
    row.status = "diverged";
    row.reason = "a position is not finite after step " + std::to_string(row.steps);
    return row;
  }

  // The errors, from the components the study names.
  for (std::size_t k = 0; k < study.errors.size(); ++k) {
    const StudyColumn& c = study.errors[k];
    const Base* component = findComponent(scene.root(), c.component);
    if (!component) {
      row.status = "no-error";
      row.reason =
          "no component '" + c.component + "' (class or name) in the scene for column " + c.column;
      return row;
    }
    std::string what;
    const double value = readNumber(*component, c.data, what);
    if (!what.empty()) {
      row.status = "no-error";
      row.reason = what;
      return row;
    }
    row.errors[k] = value * c.scale;
    if (!std::isfinite(row.errors[k])) {
      row.status = "diverged";
      row.reason = c.column + " is not finite";
      return row;
    }
  }
  return row;
}

std::string writeStudyCsv(const std::filesystem::path& file, const Study& study,
                          const std::vector<StudyRow>& rows) {
  std::ofstream out(file);
  if (!out) return "cannot write '" + file.string() + "'";
  out << "model,resolution,solver,dt,steps,steps_per_s,wall_s";
  for (const StudyColumn& c : study.errors) out << ',' << csvCell(c.column);
  if (study.errors.empty()) out << ",max_error,rms_error";
  out << ",load_s,status,reason\n";
  for (const StudyRow& r : rows) {
    for (const char* axis : {"model", "resolution", "solver"}) {
      auto it = r.axes.find(axis);
      out << csvCell(it == r.axes.end() ? "-" : it->second) << ',';
    }
    out << number(r.dt) << ',' << r.steps << ',' << number(r.stepsPerSecond()) << ','
        << number(r.wallSeconds);
    for (double e : r.errors) out << ',' << number(e);
    if (study.errors.empty()) out << ",,";
    std::string status = r.status;
    if (r.expected) status += r.failed() ? " (expected)" : " (expected a failure)";
    out << ',' << number(r.loadSeconds) << ',' << csvCell(status) << ',' << csvCell(r.reason)
        << '\n';
  }
  if (!out) return "cannot write '" + file.string() + "'";
  return {};
}

std::string writeStudyPlot(const std::filesystem::path& file, const Study& study,
                           const std::vector<StudyRow>& rows) {
  if (study.errors.empty()) return "the study names no error: no plot";
  // Which axes besides the model split the curves: those with several values among the rows.
  std::vector<std::string> splitBy;
  for (const char* axis : {"solver", "dt"}) {
    std::map<std::string, int> seen;
    for (const StudyRow& r : rows)
      if (auto it = r.axes.find(axis); it != r.axes.end()) seen[it->second]++;
    if (seen.size() > 1) splitBy.push_back(axis);
  }
  std::vector<report::ChartSeries> series;
  for (const StudyRow& r : rows) {
    if (r.failed()) continue;
    std::string name = r.axes.count("model") ? r.axes.at("model") : study.name;
    for (const std::string& axis : splitBy) name += " " + r.axes.at(axis);
    auto it = std::find_if(series.begin(), series.end(),
                           [&](const report::ChartSeries& s) { return s.name == name; });
    if (it == series.end()) {
      series.push_back({name, {}, {}});
      it = series.end() - 1;
    }
    it->x.push_back(r.wallSeconds);
    it->y.push_back(r.errors.front());
  }
  report::ChartAxes axes;
  axes.title = study.title;
  axes.xLabel = "wall time of the steps (s)";
  axes.yLabel = study.errorLabel;
  axes.logX = axes.logY = true;
  return report::writeChartPng(file.string(), axes, series);
}

}  // namespace stroma::cli
