// SPDX-License-Identifier: MIT
// A fixture for the tests that load small scenes using the built plugins: load an inline scene,
// find objects and Data by path, query the messages.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "simulation/Scene.h"
#include "topology/Topology.h"

namespace stroma::test {

class SceneFixture : public ::testing::Test {
 protected:
  SceneFixture() {
    static std::atomic<int> counter{0};
    m_folder =
        std::filesystem::temp_directory_path() /
        ("stroma-topology-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(m_folder);
  }
  ~SceneFixture() override {
    scene.unload();
    std::error_code ignored;
    std::filesystem::remove_all(m_folder, ignored);
  }

  /// Writes a file in the test's folder and returns its path.
  std::string write(const std::string& name, std::string_view bytes) {
    const auto path = m_folder / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }
  /// A file of tests/plugins/MeshIO/data.
  static std::string data(const std::string& name) {
    return (std::filesystem::path(STROMA_SOURCE_DIR) / "tests/plugins/MeshIO/data" / name).string();
  }

  bool load(std::string_view xml) {
    const auto file = m_folder / "scene.scn";
    std::ofstream(file) << xml;
    return scene.loadFile(file);
  }

  Base* object(const std::string& path) {
    std::string why;
    Base* found = resolveObjectPath(scene.root(), path, why);
    EXPECT_NE(found, nullptr) << path << ": " << why;
    return found;
  }
  Topology* topology(const std::string& path) {
    auto* t = dynamic_cast<Topology*>(object(path));
    EXPECT_NE(t, nullptr) << path << " is not a Topology";
    return t;
  }
  std::string value(const std::string& path, const std::string& field) {
    Base* o = object(path);
    const BaseData* d = o ? o->findData(field) : nullptr;
    EXPECT_NE(d, nullptr) << path << "." << field;
    return d ? d->valueText() : "";
  }

  std::string messages() {
    std::string text;
    for (const Message& m : scene.log().messages()) text += formatForConsole(m) + "\n";
    return text.empty() ? "(no messages)" : text;
  }
  std::vector<Message> messagesAt(MessageLevel level) {
    std::vector<Message> result;
    for (Message& m : scene.log().messages())
      if (m.level == level) result.push_back(std::move(m));
    return result;
  }
  /// The first message of `level` containing `part` (a default Message when none).
  Message find(MessageLevel level, std::string_view part) {
    for (Message& m : messagesAt(level))
      if (m.text.find(part) != std::string::npos) return m;
    ADD_FAILURE() << "no message containing '" << part << "' in:\n" << messages();
    return {};
  }

  Runtime runtime;
  Scene scene{runtime};

 private:
  std::filesystem::path m_folder;
};

}  // namespace stroma::test
