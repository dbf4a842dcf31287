// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Base.h"
#include "core/StateTypes.h"
#include "topology/TopologyTypes.h"

namespace stroma {

/// Selects the points, and the elements, inside spheres (SOFA's SphereROI). A data engine, as
/// BoxROI: its outputs are recomputed when read after an input changed.
///
/// A point p is inside when |p - c_j| <= r_j for one sphere j. An edge, triangle, quad or
/// tetrahedron is inside when all its points are inside one same sphere, and, for edges when
/// edgeAngle > 0, its direction makes an angle of at most edgeAngle with +-direction; for
/// triangles when triAngle > 0, its normal ((x2 - x0) x (x1 - x0), SOFA's orientation) one of at
/// most triAngle with normal. One radius for several centers is the radius of each.
/// Default inputs as BoxROI (RoiInputs.h): the node's state, a loader, the state above; the
/// element lists of the node's topology when their compute* flag is set.
class SphereROI final : public Base, public DataEngine {
 public:
  Data<std::vector<Vec3d>> d_centers{
      this, "centers", {}, "Centers of the spheres (nbSpheres x 3).", {.unit = "m"}};
  Data<std::vector<double>> d_radii{this,
                                    "radii",
                                    {},
                                    "Radii of the spheres (nbSpheres, or one for all).",
                                    {.unit = "m", .min = 0.0}};
  Data<Vec3d> d_direction{this, "direction", Vec3d(0, 0, 0),
                          "Direction the selected edges follow (when edgeAngle > 0)."};
  Data<Vec3d> d_normal{this, "normal", Vec3d(0, 0, 0),
                       "Normal of the selected triangles (when triAngle > 0)."};
  Data<double> d_edgeAngle{this, "edgeAngle", 0.0,
                           "Largest angle between a selected edge and direction (0: any).",
                           {.unit = "deg", .min = 0.0}};
  Data<double> d_triAngle{this, "triAngle", 0.0,
                          "Largest angle between a selected triangle's normal and normal (0: "
                          "any).",
                          {.unit = "deg", .min = 0.0, .alias = "angle"}};
  Data<std::vector<Vec3d>> d_position{this,
                                      "position",
                                      {},
                                      "Points to select from (nbPoints x 3); default: the rest "
                                      "positions of the node's mechanical state.",
                                      {.unit = "m", .alias = "rest_position"}};
  Data<std::vector<Edge>> d_edges{this, "edges", {}, "Edges to select from."};
  Data<std::vector<Triangle>> d_triangles{this, "triangles", {}, "Triangles to select from."};
  Data<std::vector<Quad>> d_quads{this, "quads", {}, "Quads to select from."};
  Data<std::vector<Tetrahedron>> d_tetrahedra{this, "tetrahedra", {}, "Tetrahedra to select from."};
  Data<bool> d_computeEdges{this, "computeEdges", true,
                            "Take the edges of the node's topology when none are given."};
  Data<bool> d_computeTriangles{this, "computeTriangles", true,
                                "Take the triangles of the node's topology when none are given."};
  Data<bool> d_computeQuads{this, "computeQuads", true,
                            "Take the quads of the node's topology when none are given."};
  Data<bool> d_computeTetrahedra{this, "computeTetrahedra", true,
                                 "Take the tetrahedra of the node's topology when none are "
                                 "given."};

  Data<std::vector<unsigned>> d_indices{this,
                                        "indices",
                                        {},
                                        "Indices of the points inside.",
                                        {.output = true, .alias = "pointIndices"}};
  Data<std::vector<Vec3d>> d_pointsInROI{
      this, "pointsInROI", {}, "Points inside.", {.unit = "m", .output = true}};
  Data<std::vector<unsigned>> d_edgeIndices{
      this, "edgeIndices", {}, "Indices of the edges inside.", {.output = true}};
  Data<std::vector<Edge>> d_edgesInROI{this, "edgesInROI", {}, "Edges inside.", {.output = true}};
  Data<std::vector<unsigned>> d_triangleIndices{
      this, "triangleIndices", {}, "Indices of the triangles inside.", {.output = true}};
  Data<std::vector<Triangle>> d_trianglesInROI{
      this, "trianglesInROI", {}, "Triangles inside.", {.output = true}};
  Data<std::vector<unsigned>> d_quadIndices{
      this, "quadIndices", {}, "Indices of the quads inside.", {.output = true}};
  Data<std::vector<Quad>> d_quadsInROI{this, "quadsInROI", {}, "Quads inside.", {.output = true}};
  Data<std::vector<unsigned>> d_tetrahedronIndices{
      this, "tetrahedronIndices", {}, "Indices of the tetrahedra inside.", {.output = true}};
  Data<std::vector<Tetrahedron>> d_tetrahedraInROI{
      this, "tetrahedraInROI", {}, "Tetrahedra inside.", {.output = true}};
  Data<int> d_nbIndices{this, "nbIndices", 0, "Number of points inside.", {.output = true}};

  Data<bool> d_drawSphere{this, "drawSphere", false, "Viewers only."};
  Data<bool> d_drawPoints{this, "drawPoints", false, "Viewers only."};
  Data<bool> d_drawEdges{this, "drawEdges", false, "Viewers only."};
  Data<bool> d_drawTriangles{this, "drawTriangles", false, "Viewers only."};
  Data<bool> d_drawQuads{this, "drawQuads", false, "Viewers only."};
  Data<bool> d_drawTetrahedra{this, "drawTetrahedra", false, "Viewers only."};
  Data<double> d_drawSize{this, "drawSize", 0.0, "Viewers only."};
  Data<bool> d_isVisible{this, "isVisible", false, "Viewers only."};

  SphereROI();

  void init() override;
  void reinit() override { setDirty(); }

 protected:
  void doUpdate() override;

 private:
  /// The sphere holding every point of `element`, or -1 (also for an index out of range).
  template <class Element>
  int sphereHolding(const Element& element) const;
  template <class Element>
  void select(const std::vector<Element>& elements, Data<std::vector<unsigned>>& indices,
              Data<std::vector<Element>>& inside, const char* field);

  std::vector<double> m_radii;  ///< one per center, from the last update
};

}  // namespace stroma
