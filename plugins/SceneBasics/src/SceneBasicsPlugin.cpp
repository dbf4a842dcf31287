// SPDX-License-Identifier: MIT
#include "DefaultAnimationLoop.h"
#include "RequiredPlugin.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("DefaultAnimationLoop", "The standard time step of a scene")
      .with<DefaultAnimationLoop>();
  registry.add("RequiredPlugin", "SOFA plugin declaration; accepted, never needed")
      .with<RequiredPlugin>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "SceneBasics", "0.1.0", "Animation loop and scene declarations", registerComponents);
  return &entry;
}
