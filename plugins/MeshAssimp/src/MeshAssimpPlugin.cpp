// SPDX-License-Identifier: MIT
#include "MeshAssimpLoader.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  registry
      .add("MeshAssimpLoader",
           "Reads any mesh file assimp reads (glTF, PLY, OBJ, STL, DAE, FBX, OFF...), node "
           "transforms applied, with its material for visual models")
      .with<stroma::MeshAssimpLoader>()
      .alias("AssimpLoader");  // the name in SOFA's SofaAssimp plugin
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "MeshAssimp", "0.1.0", "Mesh files of every format assimp reads (MeshAssimpLoader)",
      registerComponents);
  return &entry;
}
