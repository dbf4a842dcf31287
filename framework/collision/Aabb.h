// SPDX-License-Identifier: MIT
// Axis-aligned bounding box: what collision models give the broad and mid phases for each of
// their primitives, and what the trees over them are made of.
#pragma once

#include <limits>

#include "core/Types.h"

namespace stroma {

/// An axis-aligned box, the closed set min <= x <= max (componentwise). A default box is empty
/// (min = +infinity, max = -infinity): it contains nothing, overlaps nothing, and becomes the
/// box of the first point or box merged into it.
struct Aabb {
  Vec3d min = Vec3d::Constant(std::numeric_limits<double>::infinity());
  Vec3d max = Vec3d::Constant(-std::numeric_limits<double>::infinity());

  /// The box of one point (min = max = point).
  static Aabb around(const Vec3d& point) { return {point, point}; }

  /// True when the box holds no point: min > max on some axis (the default box, or a box shrunk
  /// by a negative margin past its size).
  bool empty() const { return (min.array() > max.array()).any(); }
  /// Grows the box to hold `point`.
  void expand(const Vec3d& point) {
    min = min.cwiseMin(point);
    max = max.cwiseMax(point);
  }
  /// Moves every face outwards by `margin` (length; a negative margin shrinks the box and may
  /// empty it). An empty default box stays empty.
  void expand(double margin) {
    min.array() -= margin;
    max.array() += margin;
  }
  /// Grows the box to hold `other` (merging an empty box changes nothing).
  void merge(const Aabb& other) {
    if (other.empty()) return;
    min = min.cwiseMin(other.min);
    max = max.cwiseMax(other.max);
  }
  /// True when the two closed boxes share at least one point (touching faces count); false when
  /// either is empty.
  bool overlaps(const Aabb& other) const {
    return (min.cwiseMax(other.min).array() <= max.cwiseMin(other.max).array()).all();
  }
  /// True when `point` is in the closed box.
  bool contains(const Vec3d& point) const {
    return (min.array() <= point.array()).all() && (point.array() <= max.array()).all();
  }
};

}  // namespace stroma
