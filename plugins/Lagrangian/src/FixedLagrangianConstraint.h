// SPDX-License-Identifier: MIT
#pragma once

#include <type_traits>
#include <vector>

#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalState.h"

namespace stroma {

/// SOFA's FixedLagrangianConstraint: holds points (frames) of a state at their positions of the
/// start, by Lagrange multipliers instead of the projection of FixedProjectiveConstraint, so
/// that the holding force is known (output `forces`) and the points are held by the same solve
/// as the contacts. Three bilateral rows per point, delta = x - x0; six per frame (the rotation
/// vector of q q0^-1, world axes, for the angular rows).
template <class DataTypes>
class FixedLagrangianConstraint final : public BaseLagrangianConstraint {
 public:
  static constexpr bool kRigid = std::is_same_v<DataTypes, Rigid3Types>;

  Link<Base> l_mstate{this, "mstate", "The state (default: the node's)."};
  Data<std::vector<unsigned>> d_indices{this, "indices", {}, "Points (frames) to hold."};
  Data<bool> d_fixAll{this, "fixAll", false, "Hold every point."};
  Data<std::vector<Vec3d>> d_forces{this, "forces", {},
                                    "Output: the force holding each point (Rigid3d: force, "
                                    "then torque) at the last step.",
                                    {.unit = "N", .output = true}};

  void init() override;
  void bwdInit() override;
  void buildConstraintRows(ConstraintRows& rows, double dt) override;
  void storeMultipliers(std::span<const double> lambda) override;

 private:
  MechanicalState<DataTypes>* m_state = nullptr;
  std::vector<unsigned> m_held;
  std::vector<typename DataTypes::Coord> m_start;
};

}  // namespace stroma
