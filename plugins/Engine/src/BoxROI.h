// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Base.h"
#include "core/StateTypes.h"
#include "topology/TopologyTypes.h"

namespace stroma {

namespace internal {
/// An oriented box as a frame: p = corner + s a + t b + w n is inside for s, t in [0, 1] and
/// |w| <= halfDepth; `toLocal` maps p - corner to (s, t, w).
struct OrientedBox {
  Vec3d corner;
  Mat3d toLocal;
  double halfDepth;
};
}  // namespace internal

/// Selects the points, and the elements, inside axis-aligned boxes (SOFA's BoxROI). A data
/// engine: its outputs are recomputed when read after an input changed, so that
/// `indices="@box.indices"` on another component pulls the selection when it needs it.
///
/// Inputs: `box` (xmin ymin zmin xmax ymax zmax, per box; a point on a face is inside; the unit
/// box when no box is given, as SOFA), `orientedBox` (parallelograms extruded along their
/// normal),
/// `position` (default: the rest positions of the node's mechanical state, else the positions
/// of a loader in the node, else the rest positions of the nearest state above, as SOFA), and
/// the element lists (default: those of the node's topology). An element is inside when all
/// its points are (`strict`, the default) or when its barycentre is.
/// Outputs: indices and pointsInROI, indicesOut and pointsOutROI, and per element type the
/// indices of the elements inside and the elements themselves, nbIndices.
///
/// Templated on the kind of points: Vec3d, and Vec2d and Vec1d, whose missing coordinates are 0
/// when tested against the boxes (SOFA's BoxROI<Vec2d>, <Vec1d>).
template <class DataTypes>
class BoxROI final : public Base, public DataEngine {
 public:
  using Coord = typename DataTypes::Coord;
  using VecCoord = std::vector<Coord>;
  using OrientedBox = internal::OrientedBox;

  Data<std::vector<Vec6d>> d_box{
      this, "box", {}, "Boxes 'xmin ymin zmin xmax ymax zmax' (nbBoxes x 6).", {.unit = "m"}};
  Data<std::vector<Vec<10>>> d_orientedBox{
      this,
      "orientedBox",
      {},
      "Oriented boxes 'p0 p1 p2 depth' (nbBoxes x 10): the parallelogram of corners p0, p1, p2 "
      "and p0 + p2 - p1, extruded by depth/2 on each side (alias plane: SOFA's PlaneROI).",
      {.unit = "m", .alias = "plane"}};
  Data<VecCoord> d_position{this,
                            "position",
                            {},
                            "Points to select from (nbPoints x coordinates); default: the rest "
                            "positions of the node's mechanical state.",
                            {.unit = "m"}};
  Data<std::vector<Edge>> d_edges{this, "edges", {}, "Edges to select from."};
  Data<std::vector<Triangle>> d_triangles{this, "triangles", {}, "Triangles to select from."};
  Data<std::vector<Quad>> d_quads{this, "quad", {}, "Quads to select from."};
  Data<std::vector<Tetrahedron>> d_tetrahedra{this, "tetrahedra", {}, "Tetrahedra to select from."};
  Data<std::vector<Hexahedron>> d_hexahedra{this, "hexahedra", {}, "Hexahedra to select from."};
  Data<bool> d_computeEdges{this, "computeEdges", true,
                            "Take the edges of the node's topology when none are given."};
  Data<bool> d_computeTriangles{this, "computeTriangles", true,
                                "Take the triangles of the node's topology when none are given."};
  Data<bool> d_computeQuad{this, "computeQuad", true,
                           "Take the quads of the node's topology when none are given."};
  Data<bool> d_computeTetrahedra{this, "computeTetrahedra", true,
                                 "Take the tetrahedra of the node's topology when none are "
                                 "given."};
  Data<bool> d_computeHexahedra{this, "computeHexahedra", true,
                                "Take the hexahedra of the node's topology when none are given."};
  Data<bool> d_strict{this, "strict", true,
                      "An element is inside when all its points are; else when its barycentre "
                      "is."};
  Data<bool> d_doUpdate{this, "doUpdate", true,
                        "Recompute when the inputs change; else keep the first selection."};

  Data<std::vector<unsigned>> d_indices{
      this, "indices", {}, "Indices of the points inside.", {.output = true}};
  Data<VecCoord> d_pointsInROI{
      this, "pointsInROI", {}, "Points inside.", {.unit = "m", .output = true}};
  Data<std::vector<unsigned>> d_indicesOut{
      this, "indicesOut", {}, "Indices of the points outside.", {.output = true}};
  Data<VecCoord> d_pointsOutROI{
      this, "pointsOutROI", {}, "Points outside.", {.unit = "m", .output = true}};
  Data<std::vector<unsigned>> d_edgeIndices{
      this, "edgeIndices", {}, "Indices of the edges inside.", {.output = true}};
  Data<std::vector<Edge>> d_edgesInROI{this, "edgesInROI", {}, "Edges inside.", {.output = true}};
  Data<std::vector<unsigned>> d_triangleIndices{
      this, "triangleIndices", {}, "Indices of the triangles inside.", {.output = true}};
  Data<std::vector<Triangle>> d_trianglesInROI{
      this, "trianglesInROI", {}, "Triangles inside.", {.output = true}};
  Data<std::vector<unsigned>> d_quadIndices{
      this, "quadIndices", {}, "Indices of the quads inside.", {.output = true}};
  Data<std::vector<Quad>> d_quadInROI{this, "quadInROI", {}, "Quads inside.", {.output = true}};
  Data<std::vector<unsigned>> d_tetrahedronIndices{
      this, "tetrahedronIndices", {}, "Indices of the tetrahedra inside.", {.output = true}};
  Data<std::vector<Tetrahedron>> d_tetrahedraInROI{
      this, "tetrahedraInROI", {}, "Tetrahedra inside.", {.output = true}};
  Data<std::vector<unsigned>> d_hexahedronIndices{
      this, "hexahedronIndices", {}, "Indices of the hexahedra inside.", {.output = true}};
  Data<std::vector<Hexahedron>> d_hexahedraInROI{
      this, "hexahedraInROI", {}, "Hexahedra inside.", {.output = true}};
  Data<int> d_nbIndices{this, "nbIndices", 0, "Number of points inside.", {.output = true}};

  Data<bool> d_drawBoxes{this, "drawBoxes", false, "Viewers only."};
  Data<bool> d_drawROI{this, "drawROI", false, "Viewers only."};
  Data<bool> d_drawPoints{this, "drawPoints", false, "Viewers only."};
  Data<bool> d_drawEdges{this, "drawEdges", false, "Viewers only."};
  Data<bool> d_drawTriangles{this, "drawTriangles", false, "Viewers only."};
  Data<bool> d_drawQuads{this, "drawQuads", false, "Viewers only."};
  Data<bool> d_drawTetrahedra{this, "drawTetrahedra", false, "Viewers only."};
  Data<bool> d_drawHexahedra{this, "drawHexahedra", false, "Viewers only."};
  Data<double> d_drawSize{this, "drawSize", 1.0, "Viewers only."};

  BoxROI();

  void init() override;
  void reinit() override { setDirty(); }

  /// True when p is in one of the boxes or oriented boxes (faces included).
  bool isInside(const Vec3d& p) const;

 protected:
  void doUpdate() override;

 private:
  void findDefaultInputs();
  template <std::size_t N>
  void select(const std::vector<std::array<Index, N>>& elements,
              Data<std::vector<unsigned>>& indices, Data<std::vector<std::array<Index, N>>>& inside,
              const std::string& field);

  /// The oriented boxes as frames, from d_orientedBox (false when one is degenerate).
  bool computeOrientedBoxes(std::vector<OrientedBox>& boxes) const;

  std::vector<OrientedBox> m_oriented;  ///< of the last update
  bool m_computedOnce = false;
  bool m_initialized = false;
};

}  // namespace stroma
