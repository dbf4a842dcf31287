// SPDX-License-Identifier: MIT
#pragma once

#include "IntersectionDistances.h"
#include "PrimitiveIntersection.h"

namespace stroma {

/// SOFA's NewProximityIntersection: MinProximityIntersection's tests, and triangles against
/// triangles through their own vertices (PrimitiveIntersection.h), so that two triangle models
/// collide without point models beside them; their edges against each other only with
/// useLineLine, as SOFA (its falling beam then has SOFA's contacts: 276 rows, not 393).
class NewProximityIntersection final : public Intersection {
 public:
  Data<bool> d_useLineLine{this, "useLineLine", false,
                           "Test segments against segments: line models, and the edges of two "
                           "triangles."};

  void init() override { m_distances.check(); }
  double alarmDistance() const override { return m_distances.d_alarmDistance.value(); }
  double contactDistance() const override { return m_distances.d_contactDistance.value(); }
  bool supports(PrimitiveKind a, PrimitiveKind b) const override {
    return collision::supportsKinds(a, b, settings());
  }
  void intersect(const CollisionModel& first, const CollisionModel& second,
                 std::span<const PrimitivePair> candidates,
                 std::vector<Contact>& contacts) const override {
    collision::intersectModels(first, second, candidates, settings(), contacts);
  }

 private:
  collision::IntersectionSettings settings() const {
    return {.alarmDistance = alarmDistance(),
            .contactDistance = contactDistance(),
            .triangleTriangle = true,
            .useLineLine = d_useLineLine.value()};
  }
  collision::IntersectionDistances m_distances{*this, 1.0, 0.5};
};

}  // namespace stroma
