// SPDX-License-Identifier: MIT
// OglModel: a drawn surface. Nothing of it runs in a batch run; the first updateVisual() (a
// renderer's) reads its mesh, applies its transform and material, and lets the mapping whose
// output it is prepare itself; later calls map the input's positions and recompute normals.
#pragma once

#include <string>
#include <vector>

#include "core/Types.h"
#include "simulation/VisualModel.h"

namespace stroma {

class BaseMapping;

class OglModel final : public VisualModel {
 public:

  Data<FileName> d_filename{this, "filename", {}, "Mesh file to draw (OBJ).", {.mustExist = false}};
  Data<std::vector<Vec3d>> d_position{this, "position", {}, "Vertex positions.", {.unit = "m"}};
  Data<std::vector<Vec3d>> d_restPosition{this, "restPosition", {}, "Rest vertex positions."};
  Data<std::vector<double>> d_normals{this, "normals", {},
                                      "Vertex normals, flat 'x y z' list (SOFA scenes also "
                                      "write a single 0 here for none)."};
  Data<std::vector<Vec2d>> d_texcoords{this, "texcoords", {}, "Texture coordinates."};
  Data<std::vector<Vec2i>> d_edges{this, "edges", {}, "Edges (vertex index pairs)."};
  Data<std::vector<Vec3i>> d_triangles{this, "triangles", {}, "Triangles (vertex index triples)."};
  Data<std::vector<Eigen::Matrix<int, 4, 1>>> d_quads{this, "quads", {}, "Quads (index quadruples)."};
  Data<std::string> d_vertices{this, "vertices", "", "SOFA vertex buffer (accepted, unused)."};
  Data<std::string> d_color{this, "color", "", "Color: a name ('red') or 'r g b a'."};
  Data<std::string> d_material{this, "material", "", "Material description (SOFA syntax)."};
  Data<FileName> d_texturename{this, "texturename", {}, "Texture image file.",
                               {.mustExist = false}};
  Data<Vec3d> d_translation{this, "translation", Vec3d::Zero(), "Translation.", {.unit = "m"}};
  Data<Vec3d> d_rotation{this, "rotation", Vec3d::Zero(), "Rotation about x, y, z.", {.unit = "deg"}};
  Data<Vec3d> d_scale3d{this, "scale3d", Vec3d::Ones(), "Scale."};
  Data<std::vector<double>> d_scale{this, "scale", {1.0},
                                    "Scale: one number (uniform) or three (x y z)."};
  Data<double> d_dx{this, "dx", 0.0, "Translation along x.", {.unit = "m"}};
  Data<double> d_dy{this, "dy", 0.0, "Translation along y.", {.unit = "m"}};
  Data<double> d_dz{this, "dz", 0.0, "Translation along z.", {.unit = "m"}};
  Data<double> d_rx{this, "rx", 0.0, "Rotation about x.", {.unit = "deg"}};
  Data<double> d_ry{this, "ry", 0.0, "Rotation about y.", {.unit = "deg"}};
  Data<double> d_rz{this, "rz", 0.0, "Rotation about z.", {.unit = "deg"}};
  Data<Vec2d> d_scaleTex{this, "scaleTex", Vec2d::Ones(), "Texture coordinate scale."};
  Data<bool> d_putOnlyTexCoords{this, "putOnlyTexCoords", false, "SOFA drawing option."};
  Data<bool> d_useNormals{this, "useNormals", true, "Use the given normals."};
  Data<std::vector<Vec3d>> d_normal{this, "normal", {},
                                    "Normal of each point (nbPoints x 3), as a loader gives them."};
  Data<bool> d_alphaBlend{this, "alphaBlend", false, "Blend with alpha."};
  Data<std::string> d_sfactor{this, "sfactor", "GL_SRC_ALPHA", "OpenGL source blend factor."};
  Data<std::string> d_dfactor{this, "dfactor", "GL_ONE_MINUS_SRC_ALPHA", "OpenGL destination blend factor."};
  Data<std::string> d_blendEquation{this, "blendEquation", "GL_FUNC_ADD", "OpenGL blend equation."};
  Data<std::string> d_primitiveType{this, "primitiveType", "DEFAULT", "OpenGL primitive type."};
  Data<double> d_lineWidth{this, "lineWidth", 1.0, "Line width (pixels)."};
  Data<bool> d_handleDynamicTopology{this, "handleDynamicTopology", true, "Follow topology changes."};

  void init() override;
  void updateVisual() override;
  const VisualSurface* surface() const override { return m_ready ? &m_surface : nullptr; }

 private:
  /// Reads the rest surface (from `filename`, else from the Data) and places it; false after
  /// an error.
  bool loadRestSurface();
  bool readFile(std::vector<Vec3d>& positions, std::vector<Vec3i>& triangles,
                std::vector<Vec3d>& normals, std::vector<Vec2d>& texcoords);
  void applyTransform(std::vector<Vec3d>& points, std::vector<Vec3d>& normals) const;
  void readMaterial();
  /// The mapping of this node whose visual output is this model, or nullptr.
  BaseMapping* findMapping() const;

  VisualSurface m_surface;
  BaseMapping* m_mapping = nullptr;
  bool m_prepared = false;  ///< the first updateVisual() ran
  bool m_ready = false;     ///< the surface is valid
  bool m_givenNormals = false;
};

}  // namespace stroma
