// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "core/ObjectFactory.h"

namespace stroma {

/// One plugin as its build-time index describes it (file "<Plugin>.stroma-plugin" beside the
/// library): which components it provides, so that a scene loads only the plugins it needs.
struct PluginIndexEntry {
  std::string name;
  std::filesystem::path library;  ///< absolute path of the shared library
  std::string version;
  std::string description;
  std::vector<std::string> components;  ///< class names and aliases
  /// Why this build left the plugin out (a library it needs was missing), with what to
  /// install; empty when it was built. Its components are then known but cannot be created.
  std::string unavailable;
};

/// Reads an index file. Returns false with `error` on a malformed file.
bool readPluginIndex(const std::filesystem::path& file, PluginIndexEntry& entry,
                     std::string& error);

/// Finds, loads and registers plugins into one factory.
///
/// Search path, first match wins: the directories of STROMA_PLUGIN_PATH (':'-separated), the
/// plugin directory beside the Stroma library (the install tree, or the build tree, which has
/// the same layout), and the build tree's plugin directory compiled in.
class PluginManager {
 public:
  explicit PluginManager(ObjectFactory& factory);
  ~PluginManager();
  PluginManager(const PluginManager&) = delete;
  PluginManager& operator=(const PluginManager&) = delete;

  static std::vector<std::filesystem::path> defaultSearchPath();
  void setSearchPath(std::vector<std::filesystem::path> directories);
  const std::vector<std::filesystem::path>& searchPath() const { return m_searchPath; }

  /// The plugin whose index lists this component name, or nullptr.
  const PluginIndexEntry* providerOf(std::string_view componentName);
  /// Every plugin found in the search path.
  const std::vector<PluginIndexEntry>& available();

  /// Loads a plugin by name (from the index) or by library path. Loading twice is a no-op.
  bool load(std::string_view nameOrPath, std::string& error);
  bool loadAll(std::string& error);
  bool isLoaded(std::string_view name) const;
  std::vector<std::string> loadedPlugins() const;

  /// Loads a library and reports its entry without registering it (used to write indexes).
  static bool inspectLibrary(const std::filesystem::path& library, PluginIndexEntry& entry,
                             std::string& error);

 private:
  struct Loaded {
    std::string name;
    std::filesystem::path library;
    void* handle;
  };
  void scanIfNeeded();
  bool loadLibrary(const std::filesystem::path& library, std::string& error);

  ObjectFactory& m_factory;
  std::vector<std::filesystem::path> m_searchPath;
  std::vector<PluginIndexEntry> m_index;
  bool m_scanned = false;
  std::vector<Loaded> m_loaded;
  mutable std::recursive_mutex m_mutex;
};

}  // namespace stroma
