// SPDX-License-Identifier: MIT
#pragma once

#include "PrimitiveIntersection.h"

namespace stroma {

/// SOFA's DiscreteIntersection: contacts only between primitives that interpenetrate (gap below
/// both models' contactDistance), with MinProximityIntersection's tests at zero alarm and
/// contact distances. SOFA's spheres-only scenes (Demos/liver.scn) use it.
class DiscreteIntersection final : public Intersection {
 public:
  double alarmDistance() const override { return 0; }
  double contactDistance() const override { return 0; }
  bool supports(PrimitiveKind a, PrimitiveKind b) const override {
    return collision::supportsKinds(a, b, settings());
  }
  void intersect(const CollisionModel& first, const CollisionModel& second,
                 std::span<const PrimitivePair> candidates,
                 std::vector<Contact>& contacts) const override {
    collision::intersectModels(first, second, candidates, settings(), contacts);
  }

 private:
  static collision::IntersectionSettings settings() {
    return {.alarmDistance = 0, .contactDistance = 0};
  }
};

}  // namespace stroma
