// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalState.h"

namespace stroma {

/// Joint limits as Lagrange multipliers (under FreeMotionAnimationLoop, with the contacts and
/// the other constraints): each limited joint value q keeps lower <= q <= upper by a unilateral
/// row on the bound nearer to its free value, delta = q - lower (H = +1) or upper - q (H = -1),
/// lambda >= 0 and complementary. The stop's torque (revolute) or force (prismatic) is the
/// multiplier: output `forces`, signed along the joint (positive pushes q up, off the lower
/// bound). Unlike the projective JointLimitConstraint, the stop acts in the same solve as the
/// contacts: a joint on its limit passes the load on to the contact and the other joints.
class JointLimitLagrangianConstraint final : public BaseLagrangianConstraint {
 public:
  Link<Base> l_mstate{this, "mstate", "The joint values (default: the node's Vec1d state)."};
  Data<std::vector<unsigned>> d_indices{this, "indices", {}, "Limited joint values (n)."};
  Data<std::vector<double>> d_lower{this, "lower", {}, "Lower bound of each (n), rad or m."};
  Data<std::vector<double>> d_upper{this, "upper", {}, "Upper bound of each (n), rad or m."};
  Data<std::vector<double>> d_forces{
      this, "forces", {},
      "Output: the stop's torque (N m) or force (N) on each limited joint at the last step, "
      "signed along the joint.",
      {.output = true}};

  void init() override;
  void buildConstraintRows(ConstraintRows& rows, double dt) override;
  void storeMultipliers(std::span<const double> lambda) override;

 private:
  MechanicalState<Vec1Types>* m_state = nullptr;
  std::vector<double> m_sign;  // per limited joint at the last step: +1 lower row, -1 upper row
  bool m_ready = false;
};

/// Checks indices, lower and upper of a joint limit component against `jointCount` values;
/// reports the first problem with msgError on `owner` and returns false.
bool checkJointLimits(Base& owner, const std::vector<unsigned>& indices,
                      const std::vector<double>& lower, const std::vector<double>& upper,
                      std::size_t jointCount);

}  // namespace stroma
