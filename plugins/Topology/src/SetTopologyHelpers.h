// SPDX-License-Identifier: MIT
// SOFA's companions of the set containers: the topology modifiers (which change a topology at
// run time: cutting, refining) and the geometry algorithms (geometric queries and drawing).
// Stroma accepts them with their attributes so that SOFA scenes load. Only the tetrahedron
// modifier does something (TetrahedronSetTopologyModifier.h: removing tetrahedra); the other
// modifiers do nothing yet, and drawing is a viewer's job.
#pragma once

#include <string>
#include <vector>

#include "core/Base.h"

namespace stroma {

/// A topology modifier of SOFA (PointSet, EdgeSet, TriangleSet, QuadSet, HexahedronSet):
/// accepted, does nothing yet.
class TopologyModifier final : public Base {
 public:
  Data<bool> d_propagateToDOF{this, "propagateToDOF", true,
                              "SOFA option, accepted: Stroma does not change topologies at run "
                              "time yet."};
};

/// What every geometry algorithms component of SOFA has (viewer options).
class GeometryAlgorithms : public Base {
 public:
  Data<bool> d_showIndices{this, "showIndices", false, "Draw point indices (viewers only)."};
  Data<double> d_showIndicesScale{this, "showIndicesScale", 0.02,
                                  "Size of the drawn indices (viewers only)."};
  Data<bool> d_showPointIndices{this, "showPointIndices", false,
                                "Draw point indices (viewers only)."};
  Data<std::string> d_tagMechanics{this, "tagMechanics", "",
                                   "SOFA option, accepted: tag of the mechanical state."};
};

class PointSetGeometryAlgorithms final : public GeometryAlgorithms {};

class EdgeSetGeometryAlgorithms final : public GeometryAlgorithms {
 public:
  Data<bool> d_drawEdges{this, "drawEdges", false, "Draw the edges (viewers only)."};
  Data<std::vector<double>> d_drawColorEdges{
      this, "drawColorEdges", {0.4, 1.0, 0.3, 1.0}, "Edge color, RGBA (viewers only)."};
};

class TriangleSetGeometryAlgorithms final : public GeometryAlgorithms {
 public:
  Data<bool> d_drawEdges{this, "drawEdges", false, "Draw the edges (viewers only)."};
  Data<std::vector<double>> d_drawColorEdges{
      this, "drawColorEdges", {0.4, 1.0, 0.3, 1.0}, "Edge color, RGBA (viewers only)."};
  Data<bool> d_drawTriangles{this, "drawTriangles", false, "Draw the triangles (viewers only)."};
  Data<std::vector<double>> d_drawColorTriangles{
      this, "drawColorTriangles", {0.2, 1.0, 1.0, 1.0}, "Triangle color, RGBA (viewers only)."};
  Data<bool> d_drawNormals{this, "drawNormals", false, "Draw the normals (viewers only)."};
};

class QuadSetGeometryAlgorithms final : public GeometryAlgorithms {
 public:
  Data<bool> d_drawEdges{this, "drawEdges", false, "Draw the edges (viewers only)."};
  Data<std::vector<double>> d_drawColorEdges{
      this, "drawColorEdges", {0.4, 1.0, 0.3, 1.0}, "Edge color, RGBA (viewers only)."};
  Data<bool> d_drawQuads{this, "drawQuads", false, "Draw the quads (viewers only)."};
  Data<std::vector<double>> d_drawColorQuads{
      this, "drawColorQuads", {0.0, 0.4, 0.4, 1.0}, "Quad color, RGBA (viewers only)."};
};

class TetrahedronSetGeometryAlgorithms final : public GeometryAlgorithms {
 public:
  Data<bool> d_drawEdges{this, "drawEdges", false, "Draw the edges (viewers only)."};
  Data<std::vector<double>> d_drawColorEdges{
      this, "drawColorEdges", {0.4, 1.0, 0.3, 1.0}, "Edge color, RGBA (viewers only)."};
  Data<bool> d_drawTriangles{this, "drawTriangles", false, "Draw the triangles (viewers only)."};
  Data<std::vector<double>> d_drawColorTriangles{
      this, "drawColorTriangles", {0.2, 1.0, 1.0, 1.0}, "Triangle color, RGBA (viewers only)."};
  Data<bool> d_drawTetrahedra{this, "drawTetrahedra", false, "Draw the tetrahedra (viewers only)."};
  Data<std::vector<double>> d_drawColorTetrahedra{
      this, "drawColorTetrahedra", {1.0, 1.0, 0.0, 1.0}, "Tetrahedron color, RGBA (viewers only)."};
  Data<double> d_drawScaleTetrahedra{this, "drawScaleTetrahedra", 1.0,
                                     "Scale of the drawn tetrahedra (viewers only)."};
  Data<bool> d_swapping{this, "swapping", false,
                        "Not an attribute of this component in SOFA (SOFA ignores it, some of its "
                        "scenes write it); accepted and ignored."};
};

class HexahedronSetGeometryAlgorithms final : public GeometryAlgorithms {
 public:
  Data<bool> d_drawEdges{this, "drawEdges", false, "Draw the edges (viewers only)."};
  Data<std::vector<double>> d_drawColorEdges{
      this, "drawColorEdges", {0.4, 1.0, 0.3, 1.0}, "Edge color, RGBA (viewers only)."};
  Data<bool> d_drawQuads{this, "drawQuads", false, "Draw the quads (viewers only)."};
  Data<std::vector<double>> d_drawColorQuads{
      this, "drawColorQuads", {0.0, 0.4, 0.4, 1.0}, "Quad color, RGBA (viewers only)."};
  Data<bool> d_drawHexa{this, "drawHexa", false, "Draw the hexahedra (viewers only)."};
  Data<std::vector<double>> d_drawColorHexahedra{
      this, "drawColorHexahedra", {1.0, 0.5, 0.0, 1.0}, "Hexahedron color, RGBA (viewers only)."};
  Data<double> d_drawScaleHexahedra{this, "drawScaleHexahedra", 1.0,
                                    "Scale of the drawn hexahedra (viewers only)."};
};

}  // namespace stroma
