// SPDX-License-Identifier: MIT
#include "core/PluginManager.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/Plugin.h"

namespace stroma {

namespace fs = std::filesystem;

bool readPluginIndex(const fs::path& file, PluginIndexEntry& entry, std::string& error) {
  std::ifstream in(file);
  if (!in) {
    error = "cannot read plugin index " + file.string();
    return false;
  }
  entry = {};
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (line.empty() || line[0] == '#') continue;
    const auto space = line.find(' ');
    const std::string key = line.substr(0, space);
    const std::string value = space == std::string::npos ? "" : line.substr(space + 1);
    if (key == "plugin") entry.name = value;
    else if (key == "library") entry.library = file.parent_path() / value;
    else if (key == "version") entry.version = value;
    else if (key == "description") entry.description = value;
    else if (key == "component") entry.components.push_back(value);
    else if (key == "unavailable")
      entry.unavailable = value;
    else {
      error = file.string() + ":" + std::to_string(lineNumber) + ": unknown key '" + key + "'";
      return false;
    }
  }
  if (entry.name.empty() || (entry.library.empty() && entry.unavailable.empty())) {
    error =
        file.string() + ": a plugin index needs 'plugin' and 'library' (or 'unavailable') lines";
    return false;
  }
  return true;
}

PluginManager::PluginManager(ObjectFactory& factory)
    : m_factory(factory), m_searchPath(defaultSearchPath()) {}

PluginManager::~PluginManager() {
  m_factory.clear();  // creators live in the libraries closed below
  for (auto it = m_loaded.rbegin(); it != m_loaded.rend(); ++it) dlclose(it->handle);
}

std::vector<fs::path> PluginManager::defaultSearchPath() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("STROMA_PLUGIN_PATH")) {
    std::stringstream list(env);
    std::string dir;
    while (std::getline(list, dir, ':'))
      if (!dir.empty()) dirs.emplace_back(dir);
  }
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&readPluginIndex), &info) && info.dli_fname) {
    std::error_code ec;
    const fs::path library = fs::canonical(info.dli_fname, ec);
    if (!ec) dirs.push_back(library.parent_path() / "stroma" / "plugins");
  }
#ifdef STROMA_BUILD_PLUGIN_DIR
  dirs.emplace_back(STROMA_BUILD_PLUGIN_DIR);
#endif
  return dirs;
}

void PluginManager::setSearchPath(std::vector<fs::path> directories) {
  std::lock_guard lock(m_mutex);
  m_searchPath = std::move(directories);
  m_scanned = false;
  m_index.clear();
}

void PluginManager::scanIfNeeded() {
  if (m_scanned) return;
  m_scanned = true;
  for (const auto& dir : m_searchPath) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (e.path().extension() == ".stroma-plugin") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      PluginIndexEntry entry;
      std::string error;
      if (!readPluginIndex(file, entry, error)) continue;
      const bool known = std::any_of(m_index.begin(), m_index.end(),
                                     [&](const auto& e) { return e.name == entry.name; });
      if (!known) m_index.push_back(std::move(entry));
    }
  }
}

const std::vector<PluginIndexEntry>& PluginManager::available() {
  std::lock_guard lock(m_mutex);
  scanIfNeeded();
  return m_index;
}

const PluginIndexEntry* PluginManager::providerOf(std::string_view componentName) {
  std::lock_guard lock(m_mutex);
  scanIfNeeded();
  for (const auto& entry : m_index)
    if (std::find(entry.components.begin(), entry.components.end(), componentName) !=
        entry.components.end())
      return &entry;
  return nullptr;
}

bool PluginManager::isLoaded(std::string_view name) const {
  std::lock_guard lock(m_mutex);
  return std::any_of(m_loaded.begin(), m_loaded.end(),
                     [&](const Loaded& l) { return l.name == name; });
}

std::vector<std::string> PluginManager::loadedPlugins() const {
  std::lock_guard lock(m_mutex);
  std::vector<std::string> names;
  for (const auto& l : m_loaded) names.push_back(l.name);
  return names;
}

namespace {

const PluginEntry* openEntry(const fs::path& library, void*& handle, std::string& error) {
  handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    error = "cannot load plugin library " + library.string() + ": " + (why ? why : "unknown");
    return nullptr;
  }
  using EntryFunction = const PluginEntry* (*)();
  auto function = reinterpret_cast<EntryFunction>(dlsym(handle, kPluginEntrySymbol));
  if (!function) {
    error = library.string() + " is not a Stroma plugin: it has no '" +
            std::string(kPluginEntrySymbol) + "' entry point";
    dlclose(handle);
    handle = nullptr;
    return nullptr;
  }
  const PluginEntry* entry = function();
  const PluginEntry expected = makePluginEntry("", "", "", nullptr);
  if (!entry || entry->abiVersion != expected.abiVersion || entry->cxxAbi != expected.cxxAbi ||
      entry->cxx11String != expected.cxx11String || !entry->name || !entry->registerComponents) {
    error = library.string() + " was built for another Stroma plugin ABI (plugin ABI " +
            (entry ? std::to_string(entry->abiVersion) : std::string("?")) + ", this Stroma " +
            std::to_string(kPluginAbiVersion) + "): rebuild it against this version";
    dlclose(handle);
    handle = nullptr;
    return nullptr;
  }
  return entry;
}

}  // namespace

bool PluginManager::loadLibrary(const fs::path& library, std::string& error) {
  void* handle = nullptr;
  const PluginEntry* entry = openEntry(library, handle, error);
  if (!entry) return false;
  if (isLoaded(entry->name)) {
    dlclose(handle);  // the same plugin from another path: keep the first
    return true;
  }
  try {
    PluginRegistry registry(m_factory, entry->name);
    entry->registerComponents(registry);
  } catch (const std::exception& e) {
    error = "plugin " + std::string(entry->name) + " failed to register: " + e.what();
    dlclose(handle);
    return false;
  }
  m_loaded.push_back({entry->name, library, handle});
  return true;
}

bool PluginManager::load(std::string_view nameOrPath, std::string& error) {
  std::lock_guard lock(m_mutex);
  if (isLoaded(nameOrPath)) return true;
  const fs::path asPath(nameOrPath);
  std::error_code ec;
  if (nameOrPath.find('/') != std::string_view::npos || asPath.extension() == ".so") {
    if (!fs::exists(asPath, ec)) {
      error = "plugin library " + asPath.string() + " does not exist";
      return false;
    }
    return loadLibrary(asPath, error);
  }
  scanIfNeeded();
  for (const auto& entry : m_index) {
    if (entry.name != nameOrPath) continue;
    if (!entry.unavailable.empty()) {
      error = "this build left plugin " + entry.name + " out: " + entry.unavailable;
      return false;
    }
    return loadLibrary(entry.library, error);
  }
  error = "no plugin named '" + std::string(nameOrPath) + "' in the plugin search path (";
  for (std::size_t i = 0; i < m_searchPath.size(); ++i) {
    if (i) error += ':';
    error += m_searchPath[i].string();
  }
  error += "; set STROMA_PLUGIN_PATH to add directories)";
  return false;
}

bool PluginManager::loadAll(std::string& error) {
  std::lock_guard lock(m_mutex);
  scanIfNeeded();
  bool ok = true;
  for (const auto& entry : m_index) {
    std::string one;
    if (!entry.unavailable.empty()) continue;  // left out of this build: nothing to load
    if (!isLoaded(entry.name) && !loadLibrary(entry.library, one)) {
      if (!error.empty()) error += '\n';
      error += one;
      ok = false;
    }
  }
  return ok;
}

bool PluginManager::inspectLibrary(const fs::path& library, PluginIndexEntry& result,
                                   std::string& error) {
  void* handle = nullptr;
  const PluginEntry* entry = openEntry(library, handle, error);
  if (!entry) return false;
  bool ok = true;
  {
    ObjectFactory scratch;
    try {
      PluginRegistry registry(scratch, entry->name);
      entry->registerComponents(registry);
      result = {};
      result.name = entry->name;
      result.library = library;
      result.version = entry->version ? entry->version : "";
      result.description = entry->description ? entry->description : "";
      for (const ComponentClass* c : scratch.classes()) {
        result.components.push_back(c->name);
        for (const auto& alias : c->aliases) result.components.push_back(alias);
      }
    } catch (const std::exception& e) {
      error = "plugin " + std::string(entry->name) + " failed to register: " + e.what();
      ok = false;
    }
  }  // the scratch factory holds creators from the library: destroy it before closing
  dlclose(handle);
  return ok;
}

}  // namespace stroma
