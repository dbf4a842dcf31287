// SPDX-License-Identifier: MIT
#include "UniformMass.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("UniformMass", "The same mass at every point or rigid frame; applies gravity")
      .with<UniformMass<Vec3Types>>("Vec3d")
      .with<UniformMass<Rigid3Types>>("Rigid3d");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("Mass", "0.1.0", "Masses (with gravity)", registerComponents);
  return &entry;
}
