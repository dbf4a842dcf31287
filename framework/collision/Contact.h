// SPDX-License-Identifier: MIT
// Contacts as plain data: what detection produces and a response (a penalty force field, or
// constraint rows) consumes. Detection knows nothing of responses, and responses nothing of the
// trees or the library that found the pairs (DESIGN.md section 8).
#pragma once

#include <cstdint>
#include <vector>

#include "core/Types.h"

namespace stroma {

class CollisionModel;

/// One pair of primitives closer than the intersection method's alarm distance.
///
/// Convention: `normal` is the unit direction from the first primitive to the second, so that
/// moving the first along -normal (or the second along +normal) separates them. `distance` is
/// the gap along it between the two surfaces: the distance between the two points minus the
/// primitives' radii (spheres), negative when they interpenetrate. The points are on the
/// primitives' own geometry (a sphere's point is on its surface, its center minus or plus
/// radius * normal; a box's point is on its surface, off its frame's origin, which a response
/// turns into a lever arm).
struct Contact {
  std::uint32_t primitive[2] = {0, 0};  ///< index in the first and in the second model
  Vec3d point[2] = {Vec3d::Zero(), Vec3d::Zero()};
  /// Where each point is on its primitive, as weights of the primitive's vertices: (1, 0, 0) for
  /// a point or a sphere, (1 - t, t, 0) on a segment, barycentric coordinates on a triangle.
  /// The point is sum_k weights[k] x_k + (sphere) radius * normal offset; a box has (1, 0, 0) on
  /// its frame and its point off the frame's origin.
  Vec3d weights[2] = {Vec3d(1, 0, 0), Vec3d(1, 0, 0)};
  Vec3d normal = Vec3d::UnitZ();
  double distance = 0;
};

/// Every contact found between two models (or within one, for self-collision: both pointers
/// equal) at this step.
struct ModelPairContacts {
  CollisionModel* first = nullptr;
  CollisionModel* second = nullptr;
  std::vector<Contact> contacts;
};

}  // namespace stroma
