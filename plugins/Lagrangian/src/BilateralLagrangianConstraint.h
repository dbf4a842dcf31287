// SPDX-License-Identifier: MIT
#pragma once

#include <type_traits>
#include <vector>

#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalState.h"

namespace stroma {

/// SOFA's BilateralLagrangianConstraint (old name BilateralInteractionConstraint): holds points
/// of `object1` (`first_point`) to points of `object2` (`second_point`) by Lagrange multipliers,
/// three bilateral rows per pair, delta = x2 - x1 (Vec3d); frames of two Rigid3d states are held
/// together in position and orientation, six rows per pair (the orientation rows: the rotation
/// vector of q2 q1^-1, in the world frame, for the angular velocities). The multipliers are the
/// forces (and torques) on object2 (output `forces`, one Vec3d, or two for frames, per pair).
template <class DataTypes>
class BilateralLagrangianConstraint final : public BaseLagrangianConstraint {
 public:
  static constexpr bool kRigid = std::is_same_v<DataTypes, Rigid3Types>;
  using State = MechanicalState<DataTypes>;

  Link<Base> l_object1{this, "object1", "First state (or a node holding one); default: the node's."};
  Link<Base> l_object2{this, "object2", "Second state; default: object1."};
  Data<std::vector<unsigned>> d_firstPoint{this, "first_point", {},
                                           "Points (frames) of object1 (n)."};
  Data<std::vector<unsigned>> d_secondPoint{this, "second_point", {},
                                            "Points (frames) of object2 held to them (n)."};
  Data<bool> d_activate{this, "activate", true, "Whether the constraint acts."};
  Data<bool> d_keepOrientationDifference{this, "keepOrientationDifference", false,
                                         "Rigid3d: keep the orientation difference of the start "
                                         "instead of equal orientations."};
  Data<std::vector<Vec3d>> d_forces{this, "forces", {},
                                    "Output: the force on each second point (Rigid3d: force "
                                    "then torque) at the last step.",
                                    {.unit = "N", .output = true}};

  void init() override;
  void bwdInit() override;
  void buildConstraintRows(ConstraintRows& rows, double dt) override;
  void storeMultipliers(std::span<const double> lambda) override;

 private:
  State* m_state1 = nullptr;
  State* m_state2 = nullptr;
  std::vector<Quat> m_orientationOffsets;  // keepOrientationDifference: q2_0 q1_0^-1 per pair
};

}  // namespace stroma
