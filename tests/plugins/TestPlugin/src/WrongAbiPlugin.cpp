// SPDX-License-Identifier: MIT
// A plugin built "for another Stroma": its entry point declares a plugin ABI that is not this
// one, so the plugin manager must refuse it before calling registerComponents.
#include <stdexcept>

#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry&) {
  throw std::logic_error("a plugin with the wrong ABI must never be registered");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry{stroma::kPluginAbiVersion + 100,
                                         __GXX_ABI_VERSION,
                                         STROMA_INTERNAL_CXX11_ABI,
                                         "StromaTestWrongAbi",
                                         "0.0.0",
                                         "Declares a plugin ABI from the future",
                                         registerComponents};
  return &entry;
}
