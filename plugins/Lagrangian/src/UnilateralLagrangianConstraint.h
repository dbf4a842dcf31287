// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalState.h"

namespace stroma {

/// SOFA's UnilateralLagrangianConstraint, the law of a contact, given in the scene: points
/// `second_point` of `object2` stay at least `contactDistance` beyond points `first_point` of
/// `object1` along the unit direction `normal`, n.(x2 - x1) >= contactDistance, pushed apart only
/// while touching (lambda >= 0, complementary), with Coulomb friction of coefficient `mu` on the
/// slip over the step. (SOFA creates these from its collision response; Stroma's response is
/// FrictionContactConstraint, with the same law.) Output `forces`: the force on each second
/// point at the last step.
class UnilateralLagrangianConstraint final : public BaseLagrangianConstraint {
 public:
  Link<Base> l_object1{this, "object1", "First state (default: the node's)."};
  Link<Base> l_object2{this, "object2", "Second state (default: object1)."};
  Data<std::vector<unsigned>> d_firstPoint{this, "first_point", {}, "Points of object1 (n)."};
  Data<std::vector<unsigned>> d_secondPoint{this, "second_point", {}, "Points of object2 (n)."};
  Data<Vec3d> d_normal{this, "normal", Vec3d(0, 1, 0),
                       "Direction from the first points to the second (normalized)."};
  Data<double> d_contactDistance{this, "contactDistance", 0.0,
                                 "Smallest distance along the normal.", {.unit = "m"}};
  Data<double> d_mu{this, "mu", 0.0, "Friction coefficient (0: frictionless).", {.min = 0.0}};
  Data<std::vector<Vec3d>> d_forces{this, "forces", {},
                                    "Output: the force on each second point at the last step.",
                                    {.unit = "N", .output = true}};

  void init() override;
  void bwdInit() override;
  void buildConstraintRows(ConstraintRows& rows, double dt) override;
  void storeMultipliers(std::span<const double> lambda) override;

 private:
  MechanicalState<Vec3Types>* m_state1 = nullptr;
  MechanicalState<Vec3Types>* m_state2 = nullptr;
  std::array<Vec3d, 3> m_frame;
  int m_rowsPerPair = 1;
};

}  // namespace stroma
