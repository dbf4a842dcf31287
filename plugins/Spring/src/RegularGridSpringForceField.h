// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "LinearSpring.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// Springs on a regular grid (SOFA's RegularGridSpringForceField): along the grid lines
/// (`lines*`), on both diagonals of every face (`quads*`) and on the four main diagonals of every
/// cell (`cubes*`). An nx x ny x nz grid gets
///   (nx-1) ny nz + nx (ny-1) nz + nx ny (nz-1)                    line springs,
///   2 [(nx-1)(ny-1) nz + (nx-1) ny (nz-1) + nx (ny-1)(nz-1)]      face diagonals,
///   4 (nx-1)(ny-1)(nz-1)                                          cell diagonals.
/// The grid is read from the topology's elements (a RegularGridTopology, or any mesh of
/// hexahedra, else of quads, else of edges: SpringPairs.h).
///
/// As measured on SOFA (runSofa, this project's SOFA build): stiffness and damping are per unit
/// length (a spring of rest length L gets ks = stiffness / L, kd = damping / L), and
/// `stiffness` / `damping`, when given, set every kind, overriding the kinds' own values (a
/// warning says so). Rest lengths are the distances between the grid's own points (the
/// topology's positions, as SOFA measures them on the grid), or between the state's rest
/// positions when the topology has no point list of the state's size.
///
/// Forces, exact tangent stiffness and energy: SpringKernel.h. The springs are built at init and
/// again when the topology changes; the built list is the output `spring`.
template <class DataTypes>
class RegularGridSpringForceField final : public ForceField<DataTypes> {
 public:
  using typename ForceField<DataTypes>::VecCoord;
  using typename ForceField<DataTypes>::VecDeriv;
  static constexpr int kDimension = DataTypes::derivSize;

  Data<double> d_stiffness{this,
                           "stiffness",
                           100.0,
                           "When given, the stiffness per unit length of every kind (overrides "
                           "linesStiffness, quadsStiffness and cubesStiffness).",
                           {.unit = "N", .min = 0.0}};
  Data<double> d_damping{this,
                         "damping",
                         5.0,
                         "When given, the damping per unit length of every kind (overrides "
                         "linesDamping, quadsDamping and cubesDamping).",
                         {.unit = "N s", .min = 0.0}};
  Data<double> d_linesStiffness{this,
                                "linesStiffness",
                                100.0,
                                "Stiffness per unit length of the springs along the grid lines.",
                                {.unit = "N", .min = 0.0}};
  Data<double> d_linesDamping{this,
                              "linesDamping",
                              5.0,
                              "Damping per unit length of the springs along the grid lines.",
                              {.unit = "N s", .min = 0.0}};
  Data<double> d_quadsStiffness{this,
                                "quadsStiffness",
                                100.0,
                                "Stiffness per unit length of the faces' diagonal springs.",
                                {.unit = "N", .min = 0.0}};
  Data<double> d_quadsDamping{this,
                              "quadsDamping",
                              5.0,
                              "Damping per unit length of the faces' diagonal springs.",
                              {.unit = "N s", .min = 0.0}};
  Data<double> d_cubesStiffness{this,
                                "cubesStiffness",
                                100.0,
                                "Stiffness per unit length of the cells' diagonal springs.",
                                {.unit = "N", .min = 0.0}};
  Data<double> d_cubesDamping{this,
                              "cubesDamping",
                              5.0,
                              "Damping per unit length of the cells' diagonal springs.",
                              {.unit = "N s", .min = 0.0}};
  Data<std::vector<LinearSpring>> d_springs{
      this, "spring", {}, "The springs built from the grid (output).", {.output = true}};
  Link<Topology> l_topology{this, "topology",
                            "Topology whose grid gives the springs (default: the nearest one "
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
  void build();

  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = 0;
};

}  // namespace stroma
