// SPDX-License-Identifier: MIT
// The two distances of the proximity intersection methods, as a member that registers its Data
// on the component (no base class, STYLE.md section 4).
#pragma once

#include "collision/CollisionPipeline.h"
#include "core/Data.h"
#include "core/Message.h"

namespace stroma::collision {

class IntersectionDistances {
 public:
  IntersectionDistances(Intersection& owner, double alarm, double contact)
      : m_owner(owner),
        d_alarmDistance{&m_owner,
                        "alarmDistance",
                        alarm,
                        "Pairs of primitives closer than this (plus both models' "
                        "contactDistance) are contacts.",
                        {.unit = "m", .min = 0.0}},
        d_contactDistance{&m_owner,
                          "contactDistance",
                          contact,
                          "Gap that the responses keep between the surfaces: penalty forces "
                          "start below it (at most alarmDistance).",
                          {.unit = "m", .min = 0.0}} {}

 private:
  Intersection& m_owner;  // first: the Data below registers with it

 public:
  Data<double> d_alarmDistance;
  Data<double> d_contactDistance;

  /// Bad input: contactDistance above alarmDistance (no contact would be found before the
  /// response must act). Returns false after the error.
  bool check() {
    if (d_contactDistance.value() <= d_alarmDistance.value()) return true;
    m_owner.msgError("contactDistance " + formatNumber(d_contactDistance.value()) +
                         " is above alarmDistance " + formatNumber(d_alarmDistance.value()) +
                         ": contacts are found within alarmDistance, so it must be at least "
                         "contactDistance",
                     "alarmDistance");
    return false;
  }
};

}  // namespace stroma::collision
