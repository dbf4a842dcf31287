// SPDX-License-Identifier: MIT
// Oriented boxes (OBBCollisionModel) against every kind of primitive, by GJK/EPA with the exact
// refinement of kernels/ConvexContact.h. PrimitiveIntersection calls it for any pair with a box;
// the rules for the other primitive follow those of the other tests (PrimitiveIntersection.h):
//   box       the two boxes (a face contact gives up to 8 points)
//   sphere    its centre as a point, the radius taken off the gap; its point is on its surface
//   point     the point
//   line      the segment; a contact at an end (parameter within 1e-6 of it) is left to the
//             point model, as SOFA does for segments
//   triangle  the triangle, on the side of its normal unless bothSide (a box whose centre is
//             behind it has no contact); a contact on one of its edges or vertices is kept by
//             the triangle that owns that feature, and only when no line (point) model of the
//             surface tests the edges (vertices), so that a box resting on a triangulated floor
//             gets each point of its contact polygon once
// Contacts follow Contact.h with the box first: the normal from the box to the other primitive,
// the box's point on its surface (off the frame's origin: the response turns it into a lever
// arm), weights (1, 0, 0) on the box.
#pragma once

#include <array>
#include <cstdint>

#include "collision/CollisionModel.h"
#include "collision/Contact.h"

namespace stroma::collision {

inline constexpr int kMaxBoxContacts = 16;

/// Writes to `out` the contacts (at most kMaxBoxContacts) of box i of `box` against primitive j
/// of `other` whose gap is below `limit`, and returns their number. `otherBothSide` is the other
/// model's bothSide (triangles).
int intersectBox(const CollisionGeometry& box, std::uint32_t i, const CollisionGeometry& other,
                 std::uint32_t j, bool otherBothSide, double limit,
                 std::array<Contact, kMaxBoxContacts>& out);

}  // namespace stroma::collision
