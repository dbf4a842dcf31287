// SPDX-License-Identifier: MIT
// Closed triangle meshes of URDF's geometric primitives (box, cylinder, sphere), centred on
// their frame as URDF places them (a cylinder along its z axis), triangles turning
// counterclockwise seen from outside, so that they can be drawn and collided like the links'
// mesh files. Free of components.
#pragma once

#include <vector>

#include "core/Types.h"

namespace stroma {

struct PrimitiveMesh {
  std::vector<Vec3d> points;
  std::vector<Vec3i> triangles;
};

/// A box of edge lengths `size` (x, y, z): 8 points, 12 triangles.
PrimitiveMesh boxMesh(const Vec3d& size);
/// A cylinder of `radius` and `length` along z, its side a prism of `segments` faces, closed by
/// two fans around a centre point.
PrimitiveMesh cylinderMesh(double radius, double length, int segments = 32);
/// A sphere of `radius`: `rings` bands of latitude, `segments` of longitude, with a point at
/// each pole.
PrimitiveMesh sphereMesh(double radius, int rings = 12, int segments = 24);

/// The points moved by the frame `frame` (rotation then translation).
void transformMesh(PrimitiveMesh& mesh, const RigidCoord3& frame);

}  // namespace stroma
