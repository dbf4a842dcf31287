// SPDX-License-Identifier: MIT
#pragma once

#include <array>

#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalState.h"

namespace stroma {

/// SOFA's SlidingLagrangianConstraint (old name SlidingConstraint): point `sliding_point` P of
/// `object1` slides along the segment from point `axis_1` A to point `axis_2` B of `object2`:
/// two bilateral rows across the axis, delta = n.(P - A) for the two unit normals n of the
/// axis (H: +n on P, -(1 - t) n on A and -t n on B, t the point's place on the segment), and two
/// unilateral stops at the ends, dir.(P - A) >= 0 and dir.(B - P) >= 0 (dir = (B - A) / |B - A|).
/// Output `force`: the force on the sliding point at the last step.
class SlidingLagrangianConstraint final : public BaseLagrangianConstraint {
 public:
  Link<Base> l_object1{this, "object1", "State of the sliding point (default: the node's)."};
  Link<Base> l_object2{this, "object2", "State of the axis' ends (default: object1)."};
  Data<unsigned> d_slidingPoint{this, "sliding_point", 0u, "Index of the sliding point in object1."};
  Data<unsigned> d_axis1{this, "axis_1", 0u, "Index of one end of the axis in object2."};
  Data<unsigned> d_axis2{this, "axis_2", 0u, "Index of the other end of the axis in object2."};
  Data<Vec3d> d_force{this, "force", Vec3d::Zero(),
                      "Output: the force on the sliding point at the last step.",
                      {.unit = "N", .output = true}};

  void init() override;
  void bwdInit() override;
  void buildConstraintRows(ConstraintRows& rows, double dt) override;
  void storeMultipliers(std::span<const double> lambda) override;

 private:
  MechanicalState<Vec3Types>* m_state1 = nullptr;
  MechanicalState<Vec3Types>* m_state2 = nullptr;
  std::array<Vec3d, 4> m_directions;  // of the rows, on the sliding point
};

}  // namespace stroma
