// SPDX-License-Identifier: MIT
#include "ExternalDemoComponent.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  registry.add("ExternalDemoComponent", "A component from a plugin built against an install")
      .with<externaldemo::ExternalDemoComponent>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "ExternalDemo", "0.1.0", "Out-of-tree plugin of the install test", registerComponents);
  return &entry;
}
