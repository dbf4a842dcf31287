// SPDX-License-Identifier: MIT
#include "RequiredPlugin.h"

namespace stroma {

void RequiredPlugin::init() {
  std::vector<std::string> names = d_pluginName.value();
  if (names.empty()) names.push_back(name());
  std::string list;
  for (const auto& n : names) {
    if (!list.empty()) list += ", ";
    list += n;
  }
  msgInfo("declared plugins " + list +
          ": not needed, the plugins of the scene's components are loaded on demand");
}

}  // namespace stroma
