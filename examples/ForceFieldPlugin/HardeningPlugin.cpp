// SPDX-License-Identifier: MIT
// The plugin's one entry point: its name, version, and the components it registers.
#include "HardeningAnchorForceField.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  registry
      .add("HardeningAnchorForceField",
           "Pulls points back to their rest positions with hardening springs")
      .with<hardening::HardeningAnchorForceField>("Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Hardening", "1.0.0", "Example third-party plugin: a hardening anchor force field",
      registerComponents);
  return &entry;
}
