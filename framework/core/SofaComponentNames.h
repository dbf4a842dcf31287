// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace stroma {

/// A component class of SOFA, and the Stroma components that do its job (when any).
struct SofaComponentName {
  std::string name;
  std::vector<std::string> equivalents;
};

/// The SOFA component of that name, or nullptr. The list is SofaComponentNames.txt, compiled in.
const SofaComponentName* findSofaComponent(std::string_view name);

}  // namespace stroma
