// SPDX-License-Identifier: MIT
#pragma once

#include <type_traits>

#include "ModelSupport.h"
#include "core/StateTypes.h"

namespace stroma {

/// Spheres centred on the points of the node's state (Vec3d), or on the origins of its frames
/// (Rigid3d), as collision primitives (SOFA's SphereCollisionModel): radius `radius`, or one per
/// sphere in `listRadius` (SphereLoader's output; a list of another length is warned about and,
/// as in SOFA, completed with `radius` or cut). The radii are read at init.
template <class DataTypes>
class SphereCollisionModel final : public CollisionModel {
 public:
  static constexpr bool kRigid = std::is_same_v<DataTypes, Rigid3Types>;

  Data<double> d_radius{this,
                        "radius",
                        1.0,
                        "Radius of every sphere (when listRadius is empty).",
                        {.unit = "m", .min = 0.0}};
  Data<std::vector<double>> d_listRadius{this,
                                         "listRadius",
                                         {},
                                         "Radius of each sphere (nbSpheres), or empty to use "
                                         "radius.",
                                         {.unit = "m", .min = 0.0}};
  Data<bool> d_showImpostors{this, "showImpostors", true, "Viewers only."};

  void init() override;
  void reinit() override { init(); }
  BaseMechanicalState* state() const override { return m_state; }
  void updateGeometry() override;

 private:
  MechanicalState<DataTypes>* m_state = nullptr;
  std::vector<Vec3d> m_centers;  // Rigid3d: the frames' origins
  std::vector<double> m_radii;   // listRadius, one per sphere
};

}  // namespace stroma
