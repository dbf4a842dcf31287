// SPDX-License-Identifier: MIT
#pragma once

#include "IntersectionDistances.h"
#include "PrimitiveIntersection.h"

namespace stroma {

/// SOFA's MinProximityIntersection: contacts between points, segments, triangles and spheres
/// closer than alarmDistance, each pair of features once (PrimitiveIntersection.h).
class MinProximityIntersection final : public Intersection {
 public:
  Data<bool> d_useSphereTriangle{this, "useSphereTriangle", true,
                                 "Test spheres against triangles."};
  Data<bool> d_usePointPoint{this, "usePointPoint", true, "Test points against points."};
  Data<bool> d_useLinePoint{this, "useLinePoint", true, "Test segments against points."};
  Data<bool> d_useLineLine{this, "useLineLine", true, "Test segments against segments."};
  Data<bool> d_useSurfaceNormals{this, "useSurfaceNormals", false,
                                 "SOFA option, accepted: contact normals are those of the "
                                 "closest points."};

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
            .usePointPoint = d_usePointPoint.value(),
            .useLinePoint = d_useLinePoint.value(),
            .useLineLine = d_useLineLine.value(),
            .useSphereTriangle = d_useSphereTriangle.value()};
  }
  collision::IntersectionDistances m_distances{*this, 1.0, 0.5};
};

}  // namespace stroma
