// SPDX-License-Identifier: MIT
#include "AttachProjectiveConstraint.h"
#include "BoxConstraint.h"
#include "DirectionProjectiveConstraint.h"
#include "FixedPlaneProjectiveConstraint.h"
#include "FixedProjectiveConstraint.h"
#include "LineProjectiveConstraint.h"
#include "LinearMovementProjectiveConstraint.h"
#include "PartialFixedProjectiveConstraint.h"
#include "PlaneProjectiveConstraint.h"
#include "PointProjectiveConstraint.h"
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
      .with<LinearMovementProjectiveConstraint<Vec1Types>>("Vec1d")
      .alias("LinearMovementConstraint");
  registry
      .add("FixedPlaneProjectiveConstraint",
           "Zeroes the displacement of points along a direction by projection")
      .with<FixedPlaneProjectiveConstraint>("Vec3d")
      .alias("FixedPlaneConstraint");
  registry.add("PlaneProjectiveConstraint", "Keeps points on a plane by projection")
      .with<PlaneProjectiveConstraint>("Vec3d")
      .alias("ProjectToPlaneConstraint");
  registry.add("LineProjectiveConstraint", "Keeps points on a line by projection")
      .with<LineProjectiveConstraint>("Vec3d")
      .alias("ProjectToLineConstraint");
  registry.add("PointProjectiveConstraint", "Puts points at a point and keeps them there")
      .with<PointProjectiveConstraint>("Vec3d")
      .alias("ProjectToPointConstraint");
  registry
      .add("DirectionProjectiveConstraint",
           "Lets points move only along a direction (on the line through where they start)")
      .with<DirectionProjectiveConstraint>("Vec3d")
      .alias("ProjectDirectionConstraint");
  registry
      .add("AttachProjectiveConstraint",
           "Attaches points of one state to points of another (one way) by projection")
      .with<AttachProjectiveConstraint>("Vec3d")
      .alias("AttachConstraint");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("Constraint", "0.1.0", "Projective constraints", registerComponents);
  return &entry;
}
