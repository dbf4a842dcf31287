// SPDX-License-Identifier: MIT
#pragma once

#include "IntersectionDistances.h"
#include "PrimitiveIntersection.h"

namespace stroma {

/// SOFA's LocalMinDistance: MinProximityIntersection's contacts, kept only where each side's
/// feature is a local minimum of the distance over its neighbourhood (a vertex: every edge from
/// it turns away from the other side; an edge: every triangle around it does), so that a convex
/// corner does not push along its edges (PrimitiveIntersection.h).
class LocalMinDistance final : public Intersection {
 public:
  Data<double> d_angleCone{this,
                           "angleCone",
                           0.0,
                           "Tolerance of the local-minimum test: the cosine by which a "
                           "neighbour's direction may still point towards the other side.",
                           {.min = -1.0, .max = 1.0}};
  Data<bool> d_filterIntersection{this, "filterIntersection", true,
                                  "Apply the local-minimum test (false: MinProximity's "
                                  "contacts)."};
  Data<double> d_coneFactor{this, "coneFactor", 0.5, "SOFA option, accepted."};
  Data<bool> d_useLMDFilters{this, "useLMDFilters", false, "SOFA option, accepted."};

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
            .localMinimum = d_filterIntersection.value(),
            .angleCone = d_angleCone.value()};
  }
  collision::IntersectionDistances m_distances{*this, 1.0, 0.5};
};

}  // namespace stroma
