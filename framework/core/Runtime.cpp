// SPDX-License-Identifier: MIT
#include "core/Runtime.h"

#include <dlfcn.h>

#include <cstdlib>
#include <sstream>

#include "core/NameSuggestions.h"
#include "core/SofaComponentNames.h"

namespace stroma {

namespace fs = std::filesystem;

const char* stromaVersion() { return STROMA_VERSION; }

Runtime::Runtime() : m_plugins(m_factory) {}

Runtime::~Runtime() = default;

std::unique_ptr<Base> Runtime::create(std::string_view className, std::string_view templateName,
                                      std::string_view contextTemplate, std::string& error) {
  std::lock_guard lock(m_mutex);
  if (!m_factory.find(className)) {
    if (const PluginIndexEntry* provider = m_plugins.providerOf(className)) {
      const std::string pluginName = provider->name;
      std::string loadError;
      if (!provider->unavailable.empty()) {
        error = "component '" + std::string(className) + "' is in plugin " + pluginName +
                ", which this build left out: " + provider->unavailable;
        return nullptr;
      }
      if (!m_plugins.load(pluginName, loadError)) {
        error = "component '" + std::string(className) + "' is in plugin " + pluginName +
                ", which failed to load: " + loadError;
        return nullptr;
      }
    }
    if (!m_factory.find(className)) {
      error = unknownComponentMessage(className);
      return nullptr;
    }
  }
  return m_factory.create(className, templateName, contextTemplate, error);
}

std::string Runtime::unknownComponentMessage(std::string_view className) {
  std::vector<std::string> known = m_factory.allNames();
  for (const auto& entry : m_plugins.available())
    known.insert(known.end(), entry.components.begin(), entry.components.end());
  const std::string name(className);
  const auto isKnown = [&](const std::string& n) {
    return std::find(known.begin(), known.end(), n) != known.end();
  };
  if (const SofaComponentName* sofa = findSofaComponent(name)) {
    std::string message = "'" + name + "' is a SOFA component that Stroma does not provide";
    std::vector<std::string> closest;
    for (const auto& s : sofa->equivalents)
      if (isKnown(s)) closest.push_back(s);
    if (closest.empty()) closest = nearestNames(name, known, 2);
    if (!closest.empty()) message += "; closest supported: " + quotedList(closest);
    return message;
  }
  std::string message = "unknown component '" + name + "'";
  const auto near = nearestNames(name, known);
  if (!near.empty()) message += "; did you mean " + quotedList(near) + "?";
  else message += " (`stroma list` shows the available components)";
  return message;
}

std::vector<fs::path> Runtime::dataPath() const {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("STROMA_DATA_PATH")) {
    std::stringstream list(env);
    std::string dir;
    while (std::getline(list, dir, ':'))
      if (!dir.empty()) dirs.emplace_back(dir);
  }
  {
    std::lock_guard lock(m_mutex);
    dirs.insert(dirs.end(), m_extraDataDirs.begin(), m_extraDataDirs.end());
  }
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&stromaVersion), &info) && info.dli_fname) {
    std::error_code ec;
    const fs::path library = fs::canonical(info.dli_fname, ec);
    if (!ec) dirs.push_back(library.parent_path().parent_path() / "share" / "stroma");
  }
#ifdef STROMA_SOURCE_SHARE_DIR
  dirs.emplace_back(STROMA_SOURCE_SHARE_DIR);
#endif
  return dirs;
}

void Runtime::addDataDirectory(fs::path directory) {
  std::lock_guard lock(m_mutex);
  m_extraDataDirs.push_back(std::move(directory));
}

fs::path Runtime::findFile(std::string_view name,
                           const std::vector<fs::path>& sceneDirectories) const {
  if (name.empty()) return {};
  std::error_code ec;
  const fs::path file(name);
  if (file.is_absolute()) return fs::exists(file, ec) ? file : fs::path();
  for (const auto& dir : sceneDirectories)
    if (fs::exists(dir / file, ec)) return (dir / file).lexically_normal();
  for (const auto& dir : dataPath())
    if (fs::exists(dir / file, ec)) return (dir / file).lexically_normal();
  return {};
}

}  // namespace stroma
