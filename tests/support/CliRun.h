// SPDX-License-Identifier: MIT
// Running the `stroma` command as a user runs it, from a test: its exit code and what it
// printed, and the CSV files it writes read back as cells.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {

struct CliRun {
  int exitCode = -1;   ///< -1 when the command did not exit normally
  std::string output;  ///< stdout and stderr together
};

/// Runs `binary arguments` through the shell (`arguments` quoted by the caller).
inline CliRun runCli(const std::string& binary, const std::string& arguments) {
  TempDir dir;
  const auto log = dir.path() / "output.txt";
  const std::string command =
      "\"" + binary + "\" " + arguments + " > \"" + log.string() + "\" 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

/// `stroma run` on a scene given as text, for `steps` steps.
inline CliRun runScene(const std::string& binary, const std::string& xml, int steps) {
  TempDir dir;
  const auto scene = dir.write("scene.scn", xml);
  return runCli(binary, "run \"" + scene.string() + "\" -n " + std::to_string(steps));
}

/// A CSV file as rows of cells (RFC 4180 quoting; no line breaks inside cells).
inline std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        cells.emplace_back();
      } else {
        cells.back() += c;
      }
    }
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace stroma::test
