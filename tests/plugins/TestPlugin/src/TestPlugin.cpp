// SPDX-License-Identifier: MIT
// StromaTestPlugin: small components that the loader, plugin and CLI tests use.
#include "TestCounter.h"
#include "TestEngine.h"
#include "TestInitCheck.h"
#include "TestTemplated.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  using namespace stroma::test;
  registry.add("TestCounter", "Counts its steps (test)")
      .with<TestCounter>()
      .alias("LegacyTestCounter")
      .sofaOptions({"showCount"});
  registry.add("TestEngine", "Doubles its input lazily (test)").with<TestEngine>();
  registry.add("TestLoader", "Makes points, as a mesh loader would (test)").with<TestLoader>();
  registry.add("TestTemplated", "Templated on the degrees of freedom (test)")
      .with<TestTemplated<Vec3Types>>("Vec3d")
      .with<TestTemplated<Rigid3Types>>("Rigid3d");
  registry.add("TestInitCheck", "Reports a bad value from init() (test)").with<TestInitCheck>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "StromaTestPlugin", "0.1.0", "Components for Stroma's own tests", registerComponents);
  return &entry;
}
