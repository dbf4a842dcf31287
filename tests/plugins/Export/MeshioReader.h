// SPDX-License-Identifier: MIT
// Reads a mesh file through Python's meshio (meshio_dump.py), an independent reader of the
// files the Export plugin writes. Tests skip with a message when /usr/bin/python3 or meshio is
// missing (Debian python3-meshio, scripts/install-deps.sh).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/CliRun.h"

namespace stroma::test {

struct MeshioMesh {
  std::vector<std::array<double, 3>> points;
  std::map<std::string, std::vector<std::vector<long>>> cells;  ///< by meshio cell type
  std::map<std::string, std::vector<double>> pointData;         ///< flattened
  std::map<std::string, std::vector<double>> cellData;          ///< flattened, blocks in order
  std::map<std::string, int> components;                        ///< of each field
};

/// Whether meshio can be used; `why` says what is missing.
inline bool meshioAvailable(std::string& why) {
  if (!std::filesystem::exists("/usr/bin/python3")) {
    why = "/usr/bin/python3 is missing";
    return false;
  }
  const CliRun run = runCli("/usr/bin/python3", "-c \"import meshio\"");
  if (run.exitCode != 0) why = "Python's meshio is missing (apt-get install python3-meshio)";
  return run.exitCode == 0;
}

#define STROMA_SKIP_WITHOUT_MESHIO()                                      \
  do {                                                                    \
    std::string whyNot;                                                   \
    if (!::stroma::test::meshioAvailable(whyNot)) GTEST_SKIP() << whyNot; \
  } while (0)

/// Reads `file` with meshio (`format`: meshio's name when the extension is not enough).
/// A failure is a test failure, with meshio's output.
inline MeshioMesh readWithMeshio(const std::filesystem::path& file,
                                 const std::string& format = "") {
  MeshioMesh mesh;
  const std::string script =
      std::string(STROMA_SOURCE_DIR) + "/tests/plugins/Export/meshio_dump.py";
  const CliRun run = runCli("/usr/bin/python3", "\"" + script + "\" \"" + file.string() + "\"" +
                                                    (format.empty() ? "" : " " + format));
  EXPECT_EQ(run.exitCode, 0) << "meshio could not read " << file << ":\n" << run.output;
  if (run.exitCode != 0) return mesh;
  std::istringstream in(run.output);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream head(line);
    std::string kind, name;
    std::size_t count = 0;
    head >> kind;
    if (kind == "points") {
      head >> count;
      for (std::size_t i = 0; i < count && std::getline(in, line); ++i) {
        std::istringstream row(line);
        std::array<double, 3> p{};
        row >> p[0] >> p[1] >> p[2];
        mesh.points.push_back(p);
      }
    } else if (kind == "cells") {
      head >> name >> count;
      auto& block = mesh.cells[name];
      for (std::size_t i = 0; i < count && std::getline(in, line); ++i) {
        std::istringstream row(line);
        std::vector<long> cell;
        for (long v; row >> v;) cell.push_back(v);
        block.push_back(cell);
      }
    } else if (kind == "point_data" || kind == "cell_data") {
      int components = 1;
      head >> name >> components;
      mesh.components[name] = components;
      auto& values = kind == "point_data" ? mesh.pointData[name] : mesh.cellData[name];
      const std::size_t rows = kind == "point_data" ? mesh.points.size() : [&] {
        std::size_t n = 0;
        for (const auto& [type, block] : mesh.cells) n += block.size();
        return n;
      }();
      for (std::size_t i = 0; i < rows && std::getline(in, line); ++i) {
        std::istringstream row(line);
        for (double v; row >> v;) values.push_back(v);
      }
    }
  }
  return mesh;
}

}  // namespace stroma::test
