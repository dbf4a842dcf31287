// SPDX-License-Identifier: MIT
#include "ConstantForceField.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("ConstantForceField", "Constant forces on points").with<ConstantForceField>("Vec3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "MechanicalLoad", "0.1.0", "External loads", registerComponents);
  return &entry;
}
