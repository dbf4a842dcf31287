// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Base.h"
#include "core/Types.h"
#include "formats/LoaderTransform.h"
#include "formats/MeshData.h"
#include "topology/TopologyTypes.h"

namespace stroma {

/// What every mesh loader shares (SOFA's MeshLoader attributes): the file, the transformation
/// applied to the points, the element post-processing, and the outputs other components link to
/// (`src="@loader"`, `position="@loader.position"`). A DataEngine: the file is read at init and
/// read again whenever an input changes.
///
/// Post-processing, in this order: triangulate (quads into two triangles), createSubelements
/// (faces of the volumes and edges of the faces that are missing), onlyAttachedPoints, then the
/// transformation of points and normals (scale, then rotation about x then y then z, then
/// translation; or the 4x4 `transformation`), then flipNormals.
class MeshLoader : public Base, public DataEngine {
 public:
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "Mesh file to read, relative to the scene's folder or the data path.",
                            {.autoLink = false}};
  LoaderTransform m_placement{this};
  Data<bool> d_triangulate{
      this, "triangulate", false, "Split each quad into two triangles.", {.autoLink = false}};
  Data<bool> d_createSubelements{
      this,
      "createSubelements",
      false,
      "Add the missing faces of the volumes (triangles of tetrahedra, quads of hexahedra) and "
      "the missing edges of the faces.",
      {.autoLink = false}};
  Data<bool> d_onlyAttachedPoints{this,
                                  "onlyAttachedPoints",
                                  false,
                                  "Drop the points no element uses, and renumber.",
                                  {.autoLink = false}};

  Data<std::vector<Vec3d>> d_position{
      this, "position", {}, "Points read (nbPoints x 3).", {.unit = "m", .output = true}};
  Data<std::vector<Edge>> d_edges{
      this, "edges", {}, "Edges read (nbEdges x 2 point indices).", {.output = true}};
  Data<std::vector<Triangle>> d_triangles{
      this, "triangles", {}, "Triangles read (nbTriangles x 3 point indices).", {.output = true}};
  Data<std::vector<Quad>> d_quads{
      this, "quads", {}, "Quads read (nbQuads x 4 point indices).", {.output = true}};
  Data<std::vector<Tetrahedron>> d_tetrahedra{this,
                                              "tetrahedra",
                                              {},
                                              "Tetrahedra read (nbTetrahedra x 4 point indices).",
                                              {.output = true}};
  Data<std::vector<Hexahedron>> d_hexahedra{
      this, "hexahedra", {}, "Hexahedra read (nbHexahedra x 8 point indices).", {.output = true}};
  Data<std::vector<Vec3d>> d_normals{
      this,
      "normals",
      {},
      "Normal at each point, when the file has normals (nbPoints x 3).",
      {.output = true}};

  void init() override;

 protected:
  explicit MeshLoader(MeshFormat format);

  /// Format options (OBJ seams, STL binary layout); the defaults otherwise.
  virtual MeshParseOptions parseOptions() const { return {}; }
  /// Copies what only this format produces (OBJ texture coordinates) to its own outputs.
  virtual void setFormatOutputs(const MeshData& mesh) { (void)mesh; }
  /// Outputs of the format-specific Data, cleared on failure.
  virtual void clearFormatOutputs() {}

  void doUpdate() override;

 private:
  void clearOutputs();
  MeshFormat m_format;
};

}  // namespace stroma
