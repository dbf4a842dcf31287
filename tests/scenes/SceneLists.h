// SPDX-License-Identifier: MIT
// What the scene tests share: reading a list of scenes, and whether the build left a plugin out.
#pragma once

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

}  // namespace stroma::test
