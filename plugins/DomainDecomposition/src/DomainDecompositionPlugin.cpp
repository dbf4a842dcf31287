// SPDX-License-Identifier: MIT
#include "HybridDomainDecompositionSolver.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("HybridDomainDecompositionSolver",
           "Quasi-static linear elasticity of a tetrahedral mesh split into precomputed and "
           "tensor-mass zones, solved zone by zone (seed 000's hybrid model)")
      .with<HybridDomainDecompositionSolver>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "DomainDecomposition", "0.1.0",
      "DomainDecomposition: the hybrid precomputed/tensor-mass model by domain decomposition",
      registerComponents);
  return &entry;
}
