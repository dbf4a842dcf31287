// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "core/Base.h"
#include "formats/LoaderTransform.h"
#include "formats/MeshData.h"

namespace stroma {

/// How GridMeshCreator splits each cell of its grid (SOFA's trianglePattern numbers).
enum class GridTrianglePattern { quads = 0, alternate = 1, upward = 2, downward = 3 };

/// The mesh of an nx x ny grid of points on the unit square of the plane z = 0: point
/// (i, j) is number i + nx j, at (i / (nx - 1), j / (ny - 1), 0). Each cell (corners a = (i, j),
/// b = (i+1, j), c = (i+1, j+1), d = (i, j+1)) is the quad (a b c d), or two triangles:
/// upward (a b c) (a c d), downward (a b d) (b c d), alternate the upward pair where i + j is
/// even and the downward pair where it is odd. So (nx - 1)(ny - 1) quads or 2 (nx - 1)(ny - 1)
/// triangles, counter-clockwise about +z. The edges are those of the elements, each once, in
/// the direction the first element using it goes around it, sorted by (first, second) point
/// (SOFA's order, compared on runSofa's VTK export). nx, ny >= 2.
MeshData makeGridMesh(int nx, int ny, GridTrianglePattern pattern);

/// A flat grid mesh (SOFA's GridMeshCreator, a mesh loader without a file): makeGridMesh's
/// points, edges and triangles or quads, then the loader's placement (scale, rotation about x,
/// y then z, translation). A data engine: the outputs follow `resolution`, `trianglePattern`
/// and the placement.
class GridMeshCreator final : public Base, public DataEngine {
 public:
  Data<Vec2i> d_resolution{this, "resolution", Vec2i(2, 2),
                           "Points along x and along y (each at least 2).", {.autoLink = false}};
  Data<int> d_trianglePattern{this,
                              "trianglePattern",
                              2,
                              "Cells as 0: quads, 1: alternate triangles, 2: upward triangles, "
                              "3: downward triangles.",
                              {.min = 0.0, .max = 3.0, .autoLink = false}};
  Data<std::string> d_filename{this, "filename", "",
                               "SOFA's loader attribute, accepted and unused: no file is read.",
                               {.autoLink = false}};
  LoaderTransform m_placement{this};

  Data<std::vector<Vec3d>> d_position{
      this, "position", {}, "Points (nx ny x 3).", {.unit = "m", .output = true}};
  Data<std::vector<Edge>> d_edges{this, "edges", {}, "Edges of the elements.", {.output = true}};
  Data<std::vector<Triangle>> d_triangles{
      this, "triangles", {}, "Triangles (patterns 1 to 3).", {.output = true}};
  Data<std::vector<Quad>> d_quads{this, "quads", {}, "Quads (pattern 0).", {.output = true}};

  GridMeshCreator();
  void init() override;

 protected:
  void doUpdate() override;
};

}  // namespace stroma
