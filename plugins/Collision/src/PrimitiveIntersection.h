// SPDX-License-Identifier: MIT
// The exact tests of pairs of primitives, for every pair of kinds, on the closest-point kernels
// of kernels/Proximity.h. The intersection components (MinProximityIntersection,
// NewProximityIntersection, LocalMinDistance, DiscreteIntersection) are settings of these.
//
// The features of a surface are tested where SOFA tests them, each pair of features once when
// the surface carries point, line and triangle models (as SOFA's scenes do):
//   point-point       the two points
//   point-line        the point and the interior of the segment (endpoints: point-point)
//   line-line         the interiors of both segments (endpoints: point-line)
//   point-triangle    the point and the triangle, on the side of its normal unless the model
//   sphere-triangle   is bothSide (a sphere: its centre, the radius taken off the gap). A
//                     contact inside the triangle is always kept; one on an edge or a vertex
//                     only by the triangle that owns that feature, and only when no line
//                     (point) model of the surface's node tests the edges (vertices): with
//                     SOFA's point, line and triangle models side by side the triangle keeps
//                     its interior, and a surface of triangles alone still has every contact
//   sphere-X          the centre against the whole point, segment (interior) or sphere
//   box-X             GJK/EPA made exact (BoxIntersection.h): a face contact gives the points
//                     of the contact polygon, an edge or vertex contact the closest points
//   triangle-triangle (NewProximityIntersection only) each triangle's owned vertices against
//                     the other, and with useLineLine the interiors of their owned edges
// "Interior" excludes parameters within 1e-6 of an end, as SOFA does.
#pragma once

#include <span>
#include <vector>

#include "collision/CollisionPipeline.h"

namespace stroma::collision {

struct IntersectionSettings {
  double alarmDistance = 1.0;
  double contactDistance = 0.5;
  /// LocalMinDistance: keep a contact only where each side's feature is a local minimum of the
  /// distance over its neighbourhood (CollisionGeometry::neighbors): at a vertex p, every edge
  /// (r - p) makes a non-acute angle with the direction u to the other side, u.(r - p) <=
  /// angleCone |u| |r - p|; on an edge at x, the same with the third vertices of its triangles.
  bool localMinimum = false;
  double angleCone = 0.0;
  /// NewProximityIntersection: triangle pairs through their features.
  bool triangleTriangle = false;
  /// MinProximityIntersection's switches.
  bool usePointPoint = true;
  bool useLinePoint = true;
  bool useLineLine = true;
  bool useSphereTriangle = true;
};

/// Whether the settings have a test for these kinds (in either order).
bool supportsKinds(PrimitiveKind a, PrimitiveKind b, const IntersectionSettings& settings);

/// Appends to `contacts` those of `candidates` (index in `first`, index in `second`) whose gap
/// is below alarmDistance + both models' contactDistance. Pairs that share a point of one state
/// (self-collision, or two models over one state) are skipped. Contacts follow Contact.h's
/// conventions (normal from first to second).
void intersectModels(const CollisionModel& first, const CollisionModel& second,
                     std::span<const PrimitivePair> candidates,
                     const IntersectionSettings& settings, std::vector<Contact>& contacts);

}  // namespace stroma::collision
