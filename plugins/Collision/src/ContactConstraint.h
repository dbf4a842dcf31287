// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "PenalityContactForceField.h"
#include "simulation/Constraints.h"

namespace stroma {

/// What CollisionResponse sets on a constraint response, whatever the two states' types.
class ContactConstraintBase : public BaseLagrangianConstraint {
 public:
  enum class Law { friction, stick };

  Data<std::vector<Vec3d>> d_contactForces{
      this, "contactForces", {}, "Output: the force of each contact on the second model's side "
      "at the last solve (N, minus that on the first).", {.output = true}};
  Data<Vec3d> d_force{this, "force", Vec3d::Zero(),
                      "Output: their sum, the force the second model receives (N).",
                      {.output = true}};

  explicit ContactConstraintBase(Law law) : m_law(law) {}

  /// This step's contacts (the penalty response's geometry: vertices, weights, arms, normal,
  /// rest distance); the vectors keep their capacity (no allocation once warm).
  std::vector<PenaltyContact>& contacts() { return m_contacts; }
  /// Per contact and side, the offset (world axes) from a rigid sphere's centre to its contact
  /// point: friction at the surface turns the sphere. Zero elsewhere; sized with contacts().
  std::vector<std::array<Vec3d, 2>>& surfaceOffsets() { return m_surfaceOffsets; }
  void setFriction(double mu) { m_mu = mu; }
  double friction() const { return m_mu; }
  Law law() const { return m_law; }

  void storeMultipliers(std::span<const double> lambda) override;

 protected:
  /// Rows per contact: 3 (friction, stick), 1 (frictionless: the normal row, unilateral).
  int rowsPerContact() const { return m_law == Law::friction && !(m_mu > 0) ? 1 : 3; }

  Law m_law;
  double m_mu = 0;
  std::vector<PenaltyContact> m_contacts;
  std::vector<std::array<Vec3d, 2>> m_surfaceOffsets;
  std::vector<std::array<Vec3d, 3>> m_frames;  // n, t1, t2 per contact, for the forces
};

/// The constraint response of the contacts between two collision models (SOFA's
/// FrictionContactConstraint and StickContactConstraint, created by CollisionResponse in the
/// nearest common ancestor of the two models' nodes; FreeMotionAnimationLoop solves them). Per
/// contact, with x_s the contact point of side s (its primitive's vertices weighted; on a frame,
/// its origin plus its arm turned with it) and v_s its velocity, n the normal from side 1 to
/// side 2 and t1, t2 two tangents:
///   normal row     delta_n = n.(x_2 - x_1) - restDistance (at the free positions),
///   tangent rows   delta_t = h t.(v_2 - v_1), the slip over the step (the free velocities),
/// the rows of H: +n (t) on side 2's point, -n (t) on side 1's (on a frame: the direction on
/// its origin and r x direction on its rotation). Friction: Coulomb's law with coefficient mu;
/// stick: the three rows held (delta = 0, bilateral); frictionless (mu = 0): the normal row
/// alone, unilateral. The multipliers are the contact forces on side 2.
template <class DataTypes1, class DataTypes2>
class ContactConstraint final : public ContactConstraintBase {
 public:
  ContactConstraint(MechanicalState<DataTypes1>* state1, MechanicalState<DataTypes2>* state2,
                    Law law)
      : ContactConstraintBase(law), m_state1(state1), m_state2(state2) {}

  void buildConstraintRows(ConstraintRows& rows, double dt) override;

 private:
  MechanicalState<DataTypes1>* m_state1;
  MechanicalState<DataTypes2>* m_state2;
};

}  // namespace stroma
