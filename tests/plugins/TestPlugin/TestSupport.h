// SPDX-License-Identifier: MIT
// Helpers shared by the tests that load scenes: a Runtime that finds StromaTestPlugin, a
// temporary folder, and queries on a MessageLog.
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/Message.h"
#include "core/PluginManager.h"
#include "core/Runtime.h"

namespace stroma::test {

/// Where the build puts StromaTestPlugin and its index (compile definition of the tests).
inline std::filesystem::path testPluginDirectory() { return STROMA_TEST_PLUGIN_DIR; }

/// Makes `runtime` find StromaTestPlugin first, then the plugins of the build.
inline void useTestPlugins(Runtime& runtime, std::vector<std::filesystem::path> extraFirst = {}) {
  std::vector<std::filesystem::path> dirs = std::move(extraFirst);
  dirs.push_back(testPluginDirectory());
  for (const auto& dir : PluginManager::defaultSearchPath()) dirs.push_back(dir);
  runtime.plugins().setSearchPath(std::move(dirs));
}

/// A fresh folder under the system's temporary folder, removed with its content at the end.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    m_path = std::filesystem::temp_directory_path() /
             ("stroma-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(m_path, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return m_path; }
  /// Writes `text` to `name` (relative to the folder, sub-folders made) and returns its path.
  std::filesystem::path write(const std::string& name, std::string_view text) const {
    const std::filesystem::path file = m_path / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  std::filesystem::path m_path;
};

/// Every message of the log, one a line, as the console shows them (for failure output).
inline std::string describe(const MessageLog& log) {
  std::string text;
  for (const Message& m : log.messages()) text += formatForConsole(m) + '\n';
  return text.empty() ? "(no messages)\n" : text;
}

/// The errors of the log.
inline std::vector<Message> errors(const MessageLog& log) {
  std::vector<Message> result;
  for (Message& m : log.messages())
    if (m.level == MessageLevel::error) result.push_back(std::move(m));
  return result;
}

/// Whether the log holds an error of the component at `path`, naming `field`, whose text
/// contains `text`: what every bad-input test asks.
inline bool hasError(const MessageLog& log, std::string_view path, std::string_view field,
                     std::string_view text) {
  for (const Message& m : errors(log))
    if (m.componentPath == path && m.field == field && m.text.find(text) != std::string::npos)
      return true;
  return false;
}

/// The first error whose text contains `needle`; a default Message (empty text) when none.
inline Message findError(const MessageLog& log, std::string_view needle) {
  for (Message& m : errors(log))
    if (m.text.find(needle) != std::string::npos) return m;
  return {};
}

}  // namespace stroma::test
