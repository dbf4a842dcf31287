// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "core/ObjectFactory.h"
#include "core/PluginManager.h"

namespace stroma {

/// What scenes are made with: the component factory, the plugins that fill it on demand and the
/// data search path. There is no global instance; a program makes one (or several) and passes
/// it to the scene loader. Scenes made with a Runtime must be destroyed before it.
/// Thread-safe: two threads may load scenes with the same Runtime.
class Runtime {
 public:
  Runtime();
  ~Runtime();

  ObjectFactory& factory() { return m_factory; }
  PluginManager& plugins() { return m_plugins; }

  /// Creates an object, loading the plugin that provides the class when it is not registered
  /// yet. On failure `error` says whether the class is unknown (with the nearest names), a
  /// SOFA component that Stroma lacks (with the closest supported one), or in a plugin that
  /// failed to load.
  std::unique_ptr<Base> create(std::string_view className, std::string_view templateName,
                               std::string_view contextTemplate, std::string& error);

  /// Directories searched for relative file names after the scene's folder: STROMA_DATA_PATH
  /// (':'-separated), those added here (`--data-path`), then Stroma's own share/ directory.
  std::vector<std::filesystem::path> dataPath() const;
  void addDataDirectory(std::filesystem::path directory);

  /// Resolves a file name as SOFA does: absolute as is; otherwise relative to each of
  /// `sceneDirectories`, then to the data path. Empty when no such file exists.
  std::filesystem::path findFile(std::string_view name,
                                 const std::vector<std::filesystem::path>& sceneDirectories) const;

 private:
  std::string unknownComponentMessage(std::string_view className);

  ObjectFactory m_factory;
  PluginManager m_plugins;
  std::vector<std::filesystem::path> m_extraDataDirs;
  mutable std::mutex m_mutex;
};

/// Stroma's version, "major.minor.patch".
const char* stromaVersion();

}  // namespace stroma
