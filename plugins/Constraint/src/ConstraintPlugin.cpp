// SPDX-License-Identifier: MIT
#include "BoxConstraint.h"
#include "FixedProjectiveConstraint.h"
#include "LinearMovementProjectiveConstraint.h"
#include "PartialFixedProjectiveConstraint.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("FixedProjectiveConstraint", "Fixes points or rigid frames by projection")
      .with<FixedProjectiveConstraint<Vec3Types>>("Vec3d")
      .with<FixedProjectiveConstraint<Vec2Types>>("Vec2d")
      .with<FixedProjectiveConstraint<Vec1Types>>("Vec1d")
      .with<FixedProjectiveConstraint<Rigid3Types>>("Rigid3d")
      .alias("FixedConstraint");
  registry.add("BoxConstraint", "Fixes the points inside boxes by projection")
      .with<BoxConstraint>("Vec3d");
  registry
      .add("PartialFixedProjectiveConstraint",
           "Fixes some directions of points or rigid frames by projection")
      .with<PartialFixedProjectiveConstraint<Vec3Types>>("Vec3d")
      .with<PartialFixedProjectiveConstraint<Rigid3Types>>("Rigid3d")
      .alias("PartialFixedConstraint");
  registry
      .add("LinearMovementProjectiveConstraint",
           "Moves points or rigid frames along a piecewise-linear trajectory")
      .with<LinearMovementProjectiveConstraint<Vec3Types>>("Vec3d")
      .with<LinearMovementProjectiveConstraint<Rigid3Types>>("Rigid3d")
      .alias("LinearMovementConstraint");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("Constraint", "0.1.0", "Projective constraints", registerComponents);
  return &entry;
}
