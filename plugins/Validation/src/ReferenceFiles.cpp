// SPDX-License-Identifier: MIT
#include "ReferenceFiles.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace stroma::reference {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

bool parseNumber(std::string_view text, double& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

bool readMarkerFile(const std::string& file, const std::vector<MarkerColumns>& columns,
                    std::vector<std::vector<Vec3d>>& points, std::string& error) {
  points.assign(columns.size(), {});
  std::ifstream in(file);
  if (!in) {
    error = "cannot open the marker file '" + file + "'";
    return false;
  }
  int needed = 0;
  for (const MarkerColumns& c : columns)
    for (int k : c.position) needed = std::max(needed, k + 1);
  std::string line;
  bool firstRow = true;
  for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const std::vector<std::string_view> fields = splitFields(text);
    double probe = 0;
    if (firstRow && !parseNumber(fields.front(), probe)) {  // a header line
      firstRow = false;
      continue;
    }
    firstRow = false;
    const std::string where = file + ":" + std::to_string(lineNumber) + ": ";
    if (static_cast<int>(fields.size()) < needed) {
      error = where + "expected at least " + std::to_string(needed) +
              " comma-separated numbers, got " + std::to_string(fields.size());
      return false;
    }
    for (std::size_t set = 0; set < columns.size(); ++set) {
      Vec3d p;
      for (int d = 0; d < 3; ++d) {
        const int k = columns[set].position[static_cast<std::size_t>(d)];
        double v = 0;
        if (!parseNumber(fields[static_cast<std::size_t>(k)], v) || !std::isfinite(v)) {
          error = where + "column " + std::to_string(k) + " is not a finite number ('" +
                  std::string(fields[static_cast<std::size_t>(k)]) + "')";
          return false;
        }
        p[d] = v * columns[set].scale;
      }
      points[set].push_back(p);
    }
  }
  if (points.empty() || points.front().empty()) {
    error = "the marker file '" + file + "' has no marker (no data line)";
    return false;
  }
  return true;
}

bool statePositions(const StateSnapshot& snapshot, const std::string& statePath,
                    std::vector<Vec3d>& positions, std::string& error) {
  const StateRecord* found = nullptr;
  for (const StateRecord& r : snapshot.states) {
    if (!statePath.empty() ? r.path == statePath : r.coordDimension == 3) {
      if (found && statePath.empty()) {
        error = "the snapshot at time " + std::to_string(snapshot.time) +
                " holds several 3-D states (" + found->path + ", " + r.path +
                "): name one with referencePath";
        return false;
      }
      found = &r;
      if (!statePath.empty()) break;
    }
  }
  if (!found) {
    error = statePath.empty()
                ? "no 3-D state in the snapshot at time " + std::to_string(snapshot.time)
                : "no state '" + statePath + "' in the snapshot at time " +
                      std::to_string(snapshot.time);
    return false;
  }
  if (found->coordDimension != 3) {
    error = "state '" + found->path + "' has " + std::to_string(found->coordDimension) +
            " numbers per position, not 3";
    return false;
  }
  positions.resize(found->count());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    positions[i] =
        Vec3d(found->positions[3 * i], found->positions[3 * i + 1], found->positions[3 * i + 2]);
    if (!positions[i].allFinite()) {
      error = "state '" + found->path + "' has a non-finite position at index " +
              std::to_string(i) + " (time " + std::to_string(snapshot.time) + ")";
      return false;
    }
  }
  return true;
}

const StateSnapshot* findSnapshot(const std::vector<StateSnapshot>& snapshots, double time) {
  if (snapshots.empty()) return nullptr;
  if (time < 0) return &snapshots.back();
  for (const StateSnapshot& s : snapshots)
    if (std::abs(s.time - time) <= 1e-9 * std::max(1.0, std::abs(time))) return &s;
  return nullptr;
}

}  // namespace stroma::reference
