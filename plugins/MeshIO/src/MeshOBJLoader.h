// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "MeshLoader.h"

namespace stroma {

/// Reads Wavefront OBJ files: points (v), faces (f: triangles, quads, larger polygons as
/// triangle fans) and lines (l: edges), with texture coordinates (vt) and normals (vn) per point.
class MeshOBJLoader final : public MeshLoader {
 public:
  Data<bool> d_handleSeams{this,
                           "handleSeams",
                           false,
                           "Keep texture and normal seams: one point per distinct "
                           "vertex/texture/normal corner (points are duplicated along seams).",
                           {.autoLink = false}};
  Data<bool> d_loadMaterial{this,
                            "loadMaterial",
                            true,
                            "SOFA option for viewers (materials are not read by Stroma).",
                            {.autoLink = false}};
  Data<std::vector<std::string>> d_trianglesGroups{
      this,
      "trianglesGroups",
      {},
      "Groups of triangles ('name material first count' ...); accepted, not used by Stroma.",
      {.autoLink = false}};
  Data<std::vector<Vec2d>> d_texcoords{
      this,
      "texcoords",
      {},
      "Texture coordinates of the points (nbPoints x 2), when the file has them.",
      {.output = true}};

  MeshOBJLoader() : MeshLoader(MeshFormat::obj) {
    addInput(&d_handleSeams);
    addOutput(&d_texcoords);
  }

 protected:
  MeshParseOptions parseOptions() const override {
    MeshParseOptions options;
    options.handleSeams = d_handleSeams.value();
    return options;
  }
  void setFormatOutputs(const MeshData& mesh) override { d_texcoords.setValue(mesh.texcoords); }
  void clearFormatOutputs() override { d_texcoords.setValue({}); }
};

}  // namespace stroma
