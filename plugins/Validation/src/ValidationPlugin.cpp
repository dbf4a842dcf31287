// SPDX-License-Identifier: MIT
#include "HertzContactComparison.h"
#include "ReferenceComparison.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("ReferenceComparison",
           "Error of a state's positions against an analytic solution, a reference state file "
           "or marker positions (max and RMS, relative to a reference length)")
      .with<ReferenceComparison>();
  registry
      .add("HertzContactComparison",
           "Contact force of an elastic sphere pressed on a rigid plane against Hertz's law")
      .with<HertzContactComparison>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Validation", "0.1.0",
      "Comparison of simulations with analytic and reference solutions (issue 7)",
      registerComponents);
  return &entry;
}
