// SPDX-License-Identifier: MIT
#include "OglModel.h"
#include "VisualComponents.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("OglModel", "A rendered surface (visual only)").with<OglModel>("Vec3d");
  registry.add("VisualStyle", "What a viewer displays (visual only)").with<VisualStyle>();
  registry.add("BackgroundSetting", "Viewer background (visual only)").with<BackgroundSetting>();
  registry.add("VisualGrid", "A reference grid (visual only)").with<VisualGrid>();
  registry.add("LineAxis", "Reference axes (visual only)").with<LineAxis>();
  registry.add("OglSceneFrame", "An orientation frame (visual only)").with<OglSceneFrame>();
  registry.add("OglLabel", "A text label on screen (visual only)").with<OglLabel>();
  registry.add("InteractiveCamera", "Viewer camera (visual only)").with<InteractiveCamera>();
  registry.add("LightManager", "Viewer lighting (visual only)").with<LightManager>();
  registry.add("SpotLight", "A spot light (visual only)").with<Light>();
  registry.add("DirectionalLight", "A directional light (visual only)").with<Light>();
  registry.add("PositionalLight", "A point light (visual only)").with<Light>();
  registry.add("DefaultVisualManagerLoop", "Visual update loop of a viewer (visual only)")
      .with<DefaultVisualManagerLoop>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Visual", "0.1.0", "Visual-only components, accepted in batch runs", registerComponents);
  return &entry;
}
