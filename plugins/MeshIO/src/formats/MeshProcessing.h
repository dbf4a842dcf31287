// SPDX-License-Identifier: MIT
// What loaders do to a mesh after reading it (SOFA's MeshLoader options), as kernels.
#pragma once

#include <vector>

#include "MeshData.h"

namespace stroma {

/// Splits each quad (a, b, c, d) into the triangles (a, b, c) and (a, c, d).
void triangulateQuads(MeshData& mesh);

/// Adds the sub-elements that are missing: the faces of the tetrahedra (triangles, oriented
/// outwards from their first tetrahedron) and of the hexahedra (quads), then the edges of the
/// triangles and quads. Existing elements stay first and in their order.
void createSubelements(MeshData& mesh);

/// Removes the points no element uses and renumbers the elements (normals and texture
/// coordinates follow). Returns, for each point kept, its index before.
std::vector<Index> removeUnattachedPoints(MeshData& mesh);

/// The transformation of scale, then rotation about x, then y, then z (degrees), then
/// translation: p -> R (s .* p) + t.
Eigen::Matrix4d makeTransform(const Vec3d& scale, const Vec3d& rotationDegrees,
                              const Vec3d& translation);

/// Transforms the points (p -> M p) and the normals (by the inverse transpose, renormalized).
void transformMesh(MeshData& mesh, const Eigen::Matrix4d& transform);

/// Reverses the orientation of triangles and quads and negates the normals.
void flipOrientation(MeshData& mesh);

}  // namespace stroma
