// SPDX-License-Identifier: MIT
#include "core/SofaComponentNames.h"

#include <sstream>

namespace stroma {

namespace {
// kSofaComponentNamesText, generated at configure time from SofaComponentNames.txt.
#include "SofaComponentNamesText.inc"

std::vector<SofaComponentName> parseNames() {
  std::vector<SofaComponentName> names;
  std::istringstream in(kSofaComponentNamesText);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    SofaComponentName entry;
    words >> entry.name;
    std::string equivalent;
    while (words >> equivalent) entry.equivalents.push_back(equivalent);
    if (!entry.name.empty()) names.push_back(std::move(entry));
  }
  return names;
}
}  // namespace

const SofaComponentName* findSofaComponent(std::string_view name) {
  static const std::vector<SofaComponentName> names = parseNames();  // immutable once built
  for (const auto& entry : names)
    if (entry.name == name) return &entry;
  return nullptr;
}

}  // namespace stroma
