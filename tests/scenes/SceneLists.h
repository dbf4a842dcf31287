// SPDX-License-Identifier: MIT
// What the scene tests share: reading a list of scenes, whether the build left a plugin out, and
// the fixture of the tests that run SOFA's example scenes.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/Runtime.h"

namespace stroma::test {

/// The lines of a scene list, without empty lines and '#' comments.
inline std::vector<std::string> readSceneList(const std::filesystem::path& file) {
  std::vector<std::string> scenes;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') scenes.push_back(line);
  return scenes;
}

/// Why this build left the plugin `name` out (a library it needs was missing), else empty.
inline std::string pluginLeftOut(Runtime& runtime, const std::string& name) {
  for (const auto& entry : runtime.plugins().available())
    if (entry.name == name && !entry.unavailable.empty()) return entry.unavailable;
  return {};
}

/// Fixture of the tests on SOFA's example scenes (../shared/sofa): skipped with a message where
/// they are absent; a runtime that finds their meshes (share/ and examples/ on its data path);
/// and a current folder of the test's own, removed at the end, since exporters in SOFA's scenes
/// (VTKExporter, WriteState) write there.
class SofaScenesFixture {
 public:
  inline static const std::filesystem::path kSofaDir =
      std::filesystem::path(STROMA_SHARED_DIR) / "sofa";

 protected:
  /// In SetUp; false after GTEST_SKIP's message when the scenes are absent.
  bool enterSofaFolder(const std::string& tag) {
    namespace fs = std::filesystem;
    if (!fs::is_directory(kSofaDir / "examples")) return false;
    runtime.addDataDirectory(kSofaDir / "share");
    runtime.addDataDirectory(kSofaDir / "examples");
    m_before = fs::current_path();
    m_folder = fs::temp_directory_path() / ("stroma-" + tag + "-" + std::to_string(::getpid()));
    fs::create_directories(m_folder);
    fs::current_path(m_folder);
    return true;
  }
  /// In TearDown.
  void leaveSofaFolder() {
    if (m_folder.empty()) return;
    std::filesystem::current_path(m_before);
    std::error_code ignored;
    std::filesystem::remove_all(m_folder, ignored);
  }

  Runtime runtime;

 private:
  std::filesystem::path m_before, m_folder;
};

}  // namespace stroma::test
