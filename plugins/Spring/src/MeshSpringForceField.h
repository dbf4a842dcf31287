// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "LinearSpring.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// Springs along the edges of a mesh (SOFA's MeshSpringForceField): one spring per pair of
/// points of each element of the topology: the edges (`lines*`), the 3 sides of the triangles,
/// the 6 pairs of the quads and of the tetrahedra, the 28 pairs of the hexahedra (`cubes*`).
/// A pair shared by several elements gets one spring, from the first list in that order. As in
/// SOFA, the stiffness and damping given are per unit length: a spring of rest length L gets
/// ks = stiffness / L and kd = damping / L (so that a chain of springs has a length-independent
/// response), and L is the distance at the rest positions. `stiffness` and `damping` set every
/// kind at once (SOFA's aliases); the per-kind values override them.
///
/// Forces, exact tangent stiffness and energy: SpringKernel.h. The springs are built at init
/// and again when the topology changes; the built list is the output `spring`.
///
/// Templated on the kind of points: Vec3d, Vec2d, Vec1d (a grid's points keep their first 2 or
/// 1 coordinates in the state, and the rest lengths are measured there).
template <class DataTypes>
class MeshSpringForceField final : public ForceField<DataTypes> {
 public:
  using typename ForceField<DataTypes>::VecCoord;
  using typename ForceField<DataTypes>::VecDeriv;
  static constexpr int kDimension = DataTypes::derivSize;

  Data<double> d_stiffness{this,
                           "stiffness",
                           0.0,
                           "Stiffness per unit length of every spring kind (each kind's own value "
                           "overrides it).",
                           {.unit = "N", .min = 0.0}};
  Data<double> d_damping{this,
                         "damping",
                         0.0,
                         "Damping per unit length of every spring kind.",
                         {.unit = "N s", .min = 0.0}};
  Data<double> d_linesStiffness{this,
                                "linesStiffness",
                                0.0,
                                "Stiffness per unit length of the springs on the edges.",
                                {.unit = "N", .min = 0.0}};
  Data<double> d_linesDamping{this,
                              "linesDamping",
                              0.0,
                              "Damping per unit length of the springs on the edges.",
                              {.unit = "N s", .min = 0.0}};
  Data<double> d_trianglesStiffness{this,
                                    "trianglesStiffness",
                                    0.0,
                                    "Stiffness per unit length of the triangles' springs.",
                                    {.unit = "N", .min = 0.0}};
  Data<double> d_trianglesDamping{this,
                                  "trianglesDamping",
                                  0.0,
                                  "Damping per unit length of the triangles' springs.",
                                  {.unit = "N s", .min = 0.0}};
  Data<double> d_quadsStiffness{this,
                                "quadsStiffness",
                                0.0,
                                "Stiffness per unit length of the quads' springs.",
                                {.unit = "N", .min = 0.0}};
  Data<double> d_quadsDamping{this,
                              "quadsDamping",
                              0.0,
                              "Damping per unit length of the quads' springs.",
                              {.unit = "N s", .min = 0.0}};
  Data<double> d_tetrahedraStiffness{this,
                                     "tetrahedraStiffness",
                                     0.0,
                                     "Stiffness per unit length of the tetrahedra's springs.",
                                     {.unit = "N", .min = 0.0}};
  Data<double> d_tetrahedraDamping{this,
                                   "tetrahedraDamping",
                                   0.0,
                                   "Damping per unit length of the tetrahedra's springs.",
                                   {.unit = "N s", .min = 0.0}};
  Data<double> d_tetrasStiffness{this,
                                 "tetrasStiffness",
                                 0.0,
                                 "SOFA's former name of tetrahedraStiffness.",
                                 {.unit = "N", .min = 0.0}};
  Data<double> d_tetrasDamping{this,
                               "tetrasDamping",
                               0.0,
                               "SOFA's former name of tetrahedraDamping.",
                               {.unit = "N s", .min = 0.0}};
  Data<double> d_cubesStiffness{this,
                                "cubesStiffness",
                                0.0,
                                "Stiffness per unit length of the hexahedra's springs.",
                                {.unit = "N", .min = 0.0}};
  Data<double> d_cubesDamping{this,
                              "cubesDamping",
                              0.0,
                              "Damping per unit length of the hexahedra's springs.",
                              {.unit = "N s", .min = 0.0}};
  Data<bool> d_noCompression{this, "noCompression", false,
                             "Springs resist elongation only (no force when shorter than rest)."};
  Data<Vec2i> d_localRange{this, "localRange", Vec2i(-1, -1),
                           "Keep only the springs with a point in [first, last] (-1: no bound)."};
  Data<std::vector<LinearSpring>> d_springs{
      this, "spring", {}, "The springs built from the mesh (output).", {.output = true}};
  Data<double> d_drawMinElongationRange{this, "drawMinElongationRange", 8.0, "Viewers only."};
  Data<double> d_drawMaxElongationRange{this, "drawMaxElongationRange", 15.0, "Viewers only."};
  Data<double> d_drawSpringSize{this, "drawSpringSize", 8.0, "Viewers only."};
  Data<int> d_drawMode{this, "drawMode", 0, "Viewers only."};
  Data<double> d_showArrowSize{this, "showArrowSize", 0.01, "Viewers only."};
  Link<Topology> l_topology{this, "topology",
                            "Topology whose elements give the springs (default: the nearest one "
                            "from this node up)."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

 private:
  /// Builds the springs from the topology at the rest positions; false after an error.
  bool build();
  void refresh();

  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = 0;
};

}  // namespace stroma
