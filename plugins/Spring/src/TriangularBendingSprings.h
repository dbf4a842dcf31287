// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "TopologySprings.h"
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
class TriangularBendingSprings final : public TopologySprings<DataTypes> {
 public:
  using typename TopologySprings<DataTypes>::VecCoord;
  using typename TopologySprings<DataTypes>::VecDeriv;
  using TopologySprings<DataTypes>::kDimension;
  using TopologySprings<DataTypes>::d_springs;

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
  Link<Topology> l_topology{this, "topology",
                            "Topology whose triangles give the springs (default: the nearest one "
                            "from this node up)."};

  void init() override;
  void reinit() override { init(); }


 private:
  using TopologySprings<DataTypes>::m_topology;
  using TopologySprings<DataTypes>::m_topologyRevision;
  void build() override;
};

}  // namespace stroma
