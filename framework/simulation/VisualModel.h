// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "core/Base.h"
#include "core/Types.h"

namespace stroma {

/// How a surface reflects light: SOFA's OglModel material (colors as r g b a in [0, 1]).
struct VisualMaterial {
  Vec4d ambient{0.2, 0.2, 0.2, 1.0};
  Vec4d diffuse{0.75, 0.75, 0.75, 1.0};
  Vec4d specular{1.0, 1.0, 1.0, 1.0};
  Vec4d emissive{0.0, 0.0, 0.0, 0.0};
  double shininess = 45.0;  ///< OpenGL's specular exponent, 0 to 128
};

/// A triangle surface as a renderer draws it (OglModel): positions in world coordinates (the
/// model's transform applied), one normal per position (empty until computed), texture
/// coordinates (empty when none), triangles (quads split in two).
struct VisualSurface {
  std::vector<Vec3d> positions;
  std::vector<Vec3d> normals;
  std::vector<Vec2d> texcoords;
  std::vector<Vec3i> triangles;
  VisualMaterial material;
  std::string texture;  ///< resolved path of the texture image, empty when none
  bool alphaBlend = false;
};

/// Something that only draws (a rendered mesh, a light, a style). Batch runs never call it:
/// a scene's visual components are loaded and checked, and cost nothing per step.
class VisualModel : public Base {
 public:
  /// Brings what is drawn up to date (a mapped surface follows its input); called by a
  /// renderer before drawing, never in batch. The first call does what a drawn model needs
  /// once (reading its mesh, the mapping's coordinates).
  virtual void updateVisual() {}
  /// The surface drawn, or nullptr (a light, a style, a camera). Valid after updateVisual().
  virtual const VisualSurface* surface() const { return nullptr; }
};

}  // namespace stroma
