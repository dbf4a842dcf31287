// SPDX-License-Identifier: MIT
// What a plugin provides: one C entry point returning a PluginEntry.
//
//   namespace {
//   void registerComponents(stroma::PluginRegistry& registry) {
//     registry.add("MyForceField", "What it computes").with<MyForceField>("Vec3d");
//   }
//   }  // namespace
//   extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
//     static const stroma::PluginEntry entry =
//         stroma::makePluginEntry("MyPlugin", "1.0", "What the plugin is for", registerComponents);
//     return &entry;
//   }
//
// The loader checks the ABI fields before it calls registerComponents, so a plugin built
// against other Stroma headers or another C++ ABI is refused with a message, not a crash.
#pragma once

#include "core/ObjectFactory.h"

#define STROMA_PLUGIN_EXPORT __attribute__((visibility("default")))

namespace stroma {

/// Bumped whenever a public class layout or virtual interface changes.
inline constexpr int kPluginAbiVersion = 3;

/// What a plugin's registration function receives: the factory, tagged with the plugin's name.
class PluginRegistry {
 public:
  PluginRegistry(ObjectFactory& factory, std::string pluginName)
      : m_factory(factory), m_plugin(std::move(pluginName)) {}
  ComponentRegistration add(std::string name, std::string description) {
    return m_factory.add(std::move(name), std::move(description), m_plugin);
  }
  const std::string& pluginName() const { return m_plugin; }

 private:
  ObjectFactory& m_factory;
  std::string m_plugin;
};

struct PluginEntry {
  int abiVersion;    ///< kPluginAbiVersion of the headers the plugin was compiled with
  int cxxAbi;        ///< compiler C++ ABI version (__GXX_ABI_VERSION)
  int cxx11String;   ///< libstdc++ dual ABI flag (_GLIBCXX_USE_CXX11_ABI)
  const char* name;
  const char* version;
  const char* description;
  void (*registerComponents)(PluginRegistry&);
};

#ifndef _GLIBCXX_USE_CXX11_ABI
#define STROMA_INTERNAL_CXX11_ABI 0
#else
#define STROMA_INTERNAL_CXX11_ABI _GLIBCXX_USE_CXX11_ABI
#endif

/// Fills the ABI fields with the values of the compilation that calls it (the plugin's).
constexpr PluginEntry makePluginEntry(const char* name, const char* version,
                                      const char* description,
                                      void (*registerComponents)(PluginRegistry&)) {
  return PluginEntry{kPluginAbiVersion, __GXX_ABI_VERSION, STROMA_INTERNAL_CXX11_ABI,
                     name, version, description, registerComponents};
}

/// The name of the C entry point every plugin exports.
inline constexpr const char* kPluginEntrySymbol = "stroma_plugin_entry";

}  // namespace stroma
