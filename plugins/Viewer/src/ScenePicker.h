// SPDX-License-Identifier: MIT
// What the mouse can grab: the surfaces of the scene's Vec3d mechanical states, and the point
// of one of them that a ray from the eye meets first.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/StateTypes.h"
#include "core/Types.h"
#include "simulation/MechanicalState.h"

namespace stroma {
class Node;
}

namespace stroma::viewer {

using Vec3State = MechanicalState<Vec3Types>;

/// The triangles drawn for one state, as indices of its points. Taken, first found wins, from
/// the topology of its node (the outer faces of its tetrahedra, else of its hexahedra split in
/// two triangles, else its triangles and quads), or a TriangleCollisionModel on that state.
/// No triangles: the state's points are picked one by one.
struct PickSurface {
  Vec3State* state = nullptr;
  std::vector<std::array<std::size_t, 3>> triangles;
};

/// Every Vec3d state under `root` (independent or mapped, in graph order) with its triangles.
std::vector<PickSurface> collectPickSurfaces(Node& root);

/// A grabbed point: a vertex of a state, and where the ray met the surface.
struct PickedPoint {
  Vec3State* state = nullptr;
  std::size_t index = 0;
  Vec3d hit = Vec3d::Zero();  ///< on the triangle (or the vertex itself when no triangle)
  double rayDistance = 0;     ///< from the ray's origin to `hit` along its direction
};

/// The nearest hit along the ray origin + s direction (s > 0, direction of unit length):
/// the first triangle met (Moller and Trumbore 1997) gives its vertex nearest to the hit; a
/// state without triangles gives its point nearest to the ray among those within
/// `pointTolerance` * s of it (a cone of a few pixels: the width of a pixel per unit of
/// distance times the pixels allowed). nullopt when nothing is met.
std::optional<PickedPoint> pickAlongRay(const std::vector<PickSurface>& surfaces,
                                        const Vec3d& origin, const Vec3d& direction,
                                        double pointTolerance);

/// Where a ray meets a triangle: the distance s along the ray, or nullopt (parallel, outside,
/// or behind the origin). Both faces count.
std::optional<double> intersectTriangle(const Vec3d& origin, const Vec3d& direction,
                                        const Vec3d& a, const Vec3d& b, const Vec3d& c);

}  // namespace stroma::viewer
