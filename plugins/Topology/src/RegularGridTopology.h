// SPDX-License-Identifier: MIT
#pragma once

#include "RegularGrid.h"
#include "TopologyContainer.h"

namespace stroma {

/// A regular grid of points and its hexahedra (SOFA's RegularGridTopology), in SOFA's
/// numbering (RegularGrid.h). The lists are made on first read (a DataEngine), so a component
/// that reads them before the grid's init gets them too.
///
/// Points per axis: `n`, or `nx ny nz` when all three are given, or from `cellWidth`. Extent:
/// `min` and `max`, each coordinate replaced by `xmin` ... `zmax` when given. Along an axis with
/// one point, the point is at the middle of [min, max] for x and y, at min for z (as SOFA).
/// `p0`, when given, moves the first point there. Made lists, as SOFA's: hexahedra, every quad
/// of the grid (inside ones too), triangles (each quad cut along its (0, 2) diagonal), edges
/// (those of the triangles when there are, else the grid segments).
class RegularGridTopology final : public TopologyContainer, public DataEngine {
 public:
  Data<Vec3i> d_n{
      this, "n", Vec3i(2, 2, 2), "Points along x, y and z (each >= 1).", {.min = 1.0, .max = 1e7}};
  Data<int> d_nx{
      this, "nx", 0, "Points along x; with ny and nz, replaces n.", {.min = 0.0, .max = 1e7}};
  Data<int> d_ny{
      this, "ny", 0, "Points along y; with nx and nz, replaces n.", {.min = 0.0, .max = 1e7}};
  Data<int> d_nz{
      this, "nz", 0, "Points along z; with nx and ny, replaces n.", {.min = 0.0, .max = 1e7}};
  Data<Vec3d> d_min{this, "min", Vec3d::Zero(), "Lower corner of the grid.", {.unit = "m"}};
  Data<Vec3d> d_max{this, "max", Vec3d::Ones(), "Upper corner of the grid.", {.unit = "m"}};
  Data<double> d_xmin{this, "xmin", 0.0, "Replaces min's x when given.", {.unit = "m"}};
  Data<double> d_ymin{this, "ymin", 0.0, "Replaces min's y when given.", {.unit = "m"}};
  Data<double> d_zmin{this, "zmin", 0.0, "Replaces min's z when given.", {.unit = "m"}};
  Data<double> d_xmax{this, "xmax", 1.0, "Replaces max's x when given.", {.unit = "m"}};
  Data<double> d_ymax{this, "ymax", 1.0, "Replaces max's y when given.", {.unit = "m"}};
  Data<double> d_zmax{this, "zmax", 1.0, "Replaces max's z when given.", {.unit = "m"}};
  Data<Vec3d> d_p0{this,
                   "p0",
                   Vec3d::Zero(),
                   "Position of the first point when given (the grid keeps its spacing).",
                   {.unit = "m"}};
  Data<double> d_cellWidth{this,
                           "cellWidth",
                           0.0,
                           "When > 0, the points per axis are ceil((max - min) / cellWidth) + 1.",
                           {.unit = "m", .min = 0.0}};
  Data<bool> d_computeHexaList{this, "computeHexaList", true, "Make the hexahedra."};
  Data<bool> d_computeQuadList{this, "computeQuadList", true, "Make the quads."};
  Data<bool> d_computeTriangleList{this, "computeTriangleList", true,
                                   "Make the triangles (two per quad)."};
  Data<bool> d_computeEdgeList{this, "computeEdgeList", true, "Make the edges."};
  Data<bool> d_computePointList{this, "computePointList", true, "Make the points."};
  Data<bool> d_createTexCoords{this, "createTexCoords", false,
                               "SOFA option for viewers, accepted; no texture coordinates are "
                               "made."};
  Data<bool> d_drawEdges{this, "drawEdges", false, "Draw the edges (viewers only)."};
  Data<bool> d_drawQuads{this, "drawQuads", false, "Draw the quads (viewers only)."};
  Data<bool> d_drawHexahedra{this, "drawHexahedra", false, "Draw the hexahedra (viewers only)."};

  RegularGridTopology();

  /// Points per axis, as the settings give them (each >= 1 once valid).
  GridSize gridSize() const;

 protected:
  void doUpdate() override;
};

}  // namespace stroma
