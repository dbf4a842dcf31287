// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "LinearSpring.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// Bending springs on a triangle mesh (SOFA's TriangularBendingSprings): for each edge shared by
/// two triangles, a spring between the two vertices opposite the edge, of rest length their
/// distance at the rest positions. Folding the pair along the edge shortens the spring, which
/// pushes it back flat (or back to its rest fold). `stiffness` and `damping` are those of every
/// spring (not per unit length). An edge of more than two triangles uses its first two, with a
/// warning, as SOFA does.
///
/// Forces, exact tangent stiffness and energy: SpringKernel.h. The springs are built at init and
/// again when the topology changes; the built list is the output `spring`.
template <class DataTypes>
class TriangularBendingSprings final : public ForceField<DataTypes> {
 public:
  using typename ForceField<DataTypes>::VecCoord;
  using typename ForceField<DataTypes>::VecDeriv;
  static constexpr int kDimension = DataTypes::derivSize;

  Data<double> d_stiffness{this,
                           "stiffness",
                           100000.0,
                           "Stiffness of every bending spring.",
                           {.unit = "N/m", .min = 0.0}};
  Data<double> d_damping{this,
                         "damping",
                         1.0,
                         "Damping of every bending spring, along the spring.",
                         {.unit = "N s/m", .min = 0.0}};
  Data<bool> d_showSprings{this, "showSprings", true, "Viewers only."};
  Data<std::vector<LinearSpring>> d_springs{
      this, "spring", {}, "The springs built from the mesh (output).", {.output = true}};
  Link<Topology> l_topology{this, "topology",
                            "Topology whose triangles give the springs (default: the nearest one "
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
