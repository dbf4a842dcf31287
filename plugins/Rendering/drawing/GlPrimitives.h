// SPDX-License-Identifier: MIT
// Immediate-mode drawing of meshes, points, segments, spheres and boxes (OpenGL 1.x).
#pragma once

#include <span>
#include <vector>

#include "collision/CollisionModel.h"
#include "core/Types.h"

namespace stroma::rendering {

/// Per-vertex normals: the sum of the normals of the triangles around each vertex, weighted by
/// their areas, normalized (zero for a vertex in no triangle). Triangles with an index out of
/// range are skipped.
std::vector<Vec3d> vertexNormals(std::span<const Vec3d> positions,
                                 std::span<const Vec3i> triangles);

/// A triangle mesh with what it has: normals (one per position), per-vertex colors or texture
/// coordinates (empty when none). Returns the number of triangles drawn (indices out of range
/// are skipped). The current color/material applies where no colors are given.
std::size_t drawTriangles(std::span<const Vec3d> positions, std::span<const Vec3d> normals,
                          std::span<const Vec3i> triangles, std::span<const Vec3d> colors = {},
                          std::span<const Vec2d> texcoords = {});
/// The edges of the triangles (each drawn once per triangle side). Returns the lines drawn.
std::size_t drawTriangleEdges(std::span<const Vec3d> positions, std::span<const Vec3i> triangles);

std::size_t drawPoints(std::span<const Vec3d> positions, double size);
void drawSegment(const Vec3d& a, const Vec3d& b);
/// A sphere of 12 x 8 facets, lit.
void drawSphere(const Vec3d& center, double radius);
/// The 12 edges of an oriented box.
void drawBoxEdges(const OrientedBox& box);

/// While it lives, drawing is in pixels of a width x height picture (origin at the top left, y
/// downwards), unlit, untextured and over everything; the matrices and those states come back
/// when it ends. For legends and text.
class PixelSpace {
 public:
  PixelSpace(int width, int height);
  ~PixelSpace();
  PixelSpace(const PixelSpace&) = delete;
  PixelSpace& operator=(const PixelSpace&) = delete;
};

/// Sets the front and back material from colors in [0, 1].
void setMaterial(const Vec4d& ambient, const Vec4d& diffuse, const Vec4d& specular,
                 const Vec4d& emissive, double shininess);
/// A plain material of one color (diffuse; ambient a third of it; a little specular).
void setColorMaterial(const Vec4d& color);

}  // namespace stroma::rendering
