// SPDX-License-Identifier: MIT
#pragma once

#include "collision/CollisionModel.h"

namespace stroma {

/// SOFA's CubeCollisionModel, accepted so that SOFA's scenes load: in SOFA it is not a shape but
/// the bounding-volume hierarchy of another collision model (axis-aligned cubes over its
/// elements), created by that model. Stroma's hierarchies are the Bullet trees that
/// BVHNarrowPhase keeps for each model, so this component adds no primitive and changes nothing;
/// its attributes (SOFA's collision-model settings) are read and unused.
class CubeCollisionModel final : public CollisionModel {
 public:
  void init() override;
  BaseMechanicalState* state() const override { return nullptr; }
  void updateGeometry() override {}
};

}  // namespace stroma
