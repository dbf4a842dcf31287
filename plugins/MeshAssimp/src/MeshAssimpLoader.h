// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "AssimpReader.h"
#include "core/Base.h"
#include "core/Types.h"
#include "formats/LoaderTransform.h"
#include "topology/TopologyTypes.h"

namespace stroma {

/// Reads any mesh file assimp reads (glTF, PLY, OBJ, STL, DAE, FBX, OFF, 3DS...) with the node
/// transforms of the file applied. Its outputs are named as the other loaders' and as OglModel's
/// fields, so that `src="@loader"` gives a topology its elements and a visual model also its
/// texture coordinates, color, material and texture.
///
/// The file's meshes are merged into one, unless meshIndex or meshName picks one. Then, as the
/// other loaders do, scale, rotation about x then y then z, translation (or the 4x4
/// transformation), then flipNormals.
class MeshAssimpLoader final : public Base, public DataEngine {
 public:
  Data<FileName> d_filename{
      this, "filename", {}, "Mesh file to read, in any format assimp reads.", {.autoLink = false}};
  Data<int> d_meshIndex{this,
                        "meshIndex",
                        -1,
                        "Index of the one mesh of the file to output (-1: all merged, unless "
                        "meshName picks one).",
                        {.autoLink = false}};
  Data<std::string> d_meshName{this,
                               "meshName",
                               "",
                               "Name of the one mesh of the file to output (empty: all merged, "
                               "unless meshIndex picks one).",
                               {.autoLink = false}};
  Data<bool> d_keepQuads{this,
                         "keepQuads",
                         false,
                         "Keep the quads of the file as quads (larger polygons are split into "
                         "triangles); otherwise every polygon becomes triangles.",
                         {.autoLink = false}};
  Data<bool> d_joinIdenticalVertices{
      this,
      "joinIdenticalVertices",
      false,
      "Merge the points identical in position, normal and texture coordinates (assimp's "
      "aiProcess_JoinIdenticalVertices); otherwise points stay as the format stores them.",
      {.autoLink = false}};
  LoaderTransform m_placement{this};

  Data<std::vector<Vec3d>> d_position{
      this, "position", {}, "Points read (nbPoints x 3).", {.unit = "m", .output = true}};
  Data<std::vector<Edge>> d_edges{
      this, "edges", {}, "Lines of the file (nbEdges x 2 point indices).", {.output = true}};
  Data<std::vector<Triangle>> d_triangles{
      this, "triangles", {}, "Triangles (nbTriangles x 3 point indices).", {.output = true}};
  Data<std::vector<Quad>> d_quads{
      this, "quads", {}, "Quads, with keepQuads (nbQuads x 4 point indices).", {.output = true}};
  Data<std::vector<Vec3d>> d_normals{
      this,
      "normals",
      {},
      "Unit normal at each point: the file's, or computed by assimp (nbPoints x 3).",
      {.output = true}};
  Data<std::vector<Vec2d>> d_texcoords{
      this,
      "texcoords",
      {},
      "Texture coordinates of the points (nbPoints x 2), when the file has them.",
      {.output = true}};
  Data<std::string> d_color{this,
                            "color",
                            "",
                            "Diffuse color 'r g b a' of the (first) mesh's material; empty when "
                            "the file has no material.",
                            {.output = true}};
  Data<std::string> d_material{this,
                               "material",
                               "",
                               "The (first) mesh's material in OglModel's syntax ('name Diffuse "
                               "1 r g b a Ambient ...'); empty when the file has none.",
                               {.output = true}};
  Data<FileName> d_texturename{this,
                               "texturename",
                               {},
                               "Diffuse texture image of the (first) mesh's material, as an "
                               "absolute path; empty when none.",
                               {.output = true, .mustExist = false}};
  Data<std::vector<std::string>> d_meshNames{
      this, "meshNames", {}, "Names of the file's meshes, by index.", {.output = true}};

  MeshAssimpLoader();
  void init() override;

 protected:
  void doUpdate() override;

 private:
  /// The transformation the attributes give; false (with the error reported) when malformed.
  bool userTransform(Eigen::Matrix4d& transform);
  /// The placed meshes that meshIndex/meshName pick (all without them); empty after an error.
  std::vector<const AssimpMesh*> pickMeshes(const AssimpFile& file);
  void setMaterialOutputs(const AssimpMaterial* material);
  void clearOutputs();
};

}  // namespace stroma
