// SPDX-License-Identifier: MIT
#include "EulerExplicitSolver.h"
#include "EulerImplicitSolver.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("EulerExplicitSolver", "Explicit (symplectic by default) Euler integration")
      .with<EulerExplicitSolver>();
  registry.add("EulerImplicitSolver", "Implicit Euler with Rayleigh damping")
      .with<EulerImplicitSolver>()
      .alias("EulerImplicit");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("ODESolver", "0.1.0", "Time integration", registerComponents);
  return &entry;
}
