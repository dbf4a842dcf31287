// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "TopologySprings.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// Bending springs on a quad mesh (SOFA's QuadBendingSprings): for each edge (a, b) shared by
/// two quads, springs across it between the vertices next to a outside the edge in each quad, and
/// the same for b (as QuadularBendingSprings), each pair once. As in SOFA, the rest lengths are
/// the distances at the positions the state has at init (not its rest positions), and
/// `stiffness` and `damping` are those of every spring. `localRange` keeps the springs with a
/// point in [first, last]. An edge of more than two quads uses its first two, with a warning.
///
/// Forces, exact tangent stiffness and energy: SpringKernel.h. The springs are built at init and
/// again when the topology changes; the built list is the output `spring`.
template <class DataTypes>
class QuadBendingSprings final : public TopologySprings<DataTypes> {
 public:
  using typename TopologySprings<DataTypes>::VecCoord;
  using typename TopologySprings<DataTypes>::VecDeriv;
  using TopologySprings<DataTypes>::kDimension;
  using TopologySprings<DataTypes>::d_springs;

  Data<double> d_stiffness{
      this, "stiffness", 100.0, "Stiffness of every bending spring.", {.unit = "N/m", .min = 0.0}};
  Data<double> d_damping{this,
                         "damping",
                         5.0,
                         "Damping of every bending spring, along the spring.",
                         {.unit = "N s/m", .min = 0.0}};
  Data<Vec2i> d_localRange{this, "localRange", Vec2i(-1, -1),
                           "Keep only the springs with a point in [first, last] (-1: no bound)."};
  Link<Topology> l_topology{this, "topology",
                            "Topology whose quads give the springs (default: the nearest one "
                            "from this node up)."};

  void init() override;
  void reinit() override { init(); }


 private:
  using TopologySprings<DataTypes>::m_topology;
  using TopologySprings<DataTypes>::m_topologyRevision;
  void build() override;
};

}  // namespace stroma
