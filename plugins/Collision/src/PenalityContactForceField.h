// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "simulation/RunSummary.h"

namespace stroma {

/// One penalty contact: a point on a primitive of each state (weights of its vertices), the
/// normal from the first to the second, the gap to keep and the stiffness.
struct PenaltyContact {
  std::array<std::uint32_t, 3> vertices[2] = {{0, 0, 0}, {0, 0, 0}};
  int vertexCount[2] = {1, 1};
  Vec3d weights[2] = {Vec3d(1, 0, 0), Vec3d(1, 0, 0)};
  /// Rigid3d sides with one vertex (a frame): the contact point's offset from the frame's origin
  /// in the frame's own axes, so that the point is origin + R arm and turns with the frame (a
  /// box's surface point); zero for a sphere, whose contact force goes through its centre.
  /// Unused on Vec3d sides.
  Vec3d arm[2] = {Vec3d::Zero(), Vec3d::Zero()};
  Vec3d normal = Vec3d::UnitZ();
  /// The gap the response keeps between the two weighted points along the normal: the
  /// intersection's contactDistance, both models' contactDistance and the spheres' radii.
  double restDistance = 0;
  double stiffness = 0;
};

/// Penalty response of the contacts between two collision models (SOFA's
/// PenalityContactForceField, created by CollisionResponse). With x_s the contact point of side s
/// (sum_k w_s,k x_s,k on points; on a frame, its origin c_s plus its arm turned with it,
/// x_s = c_s + r_s, r_s = R_s arm_s), the normal n fixed at detection and the penetration
///   p = restDistance - n.(x_2 - x_1),
/// a contact with p > 0 pushes the sides apart with the force f = k p n at the contact points
/// (-f on side 1, +f on side 2), spread on the vertices by their weights, and on a frame the
/// force on its origin and the moment r_s x f_s on its rotation; its energy is k p^2 / 2. A
/// contact with p <= 0 does nothing.
///
/// Stiffness (addDForce, addKToMatrix): with J_s = [w_s,k I] on points and J_s = [I, -[r_s]x]
/// on a frame (dx_s = dc_s + dtheta_s x r_s, angular displacements in world axes),
///   K_st = -k sigma_s sigma_t J_s^T n n^T J_t,   sigma_1 = -1, sigma_2 = +1,
/// symmetric. It is exact for a fixed normal and fixed arms r_s; the change of r_s as the frame
/// turns adds to the rotation block of frame s the non-symmetric [f_s]x [r_s]x (f_s the force on
/// that side), of relative size about p / |r_s|, which the symmetric linear solvers cannot take
/// and which is left out, as RigidMapping leaves out its geometric stiffness. The normal's turn
/// with the surfaces is left out, as in SOFA. geometricStiffness adds the rotation term (the exact
/// tangent, non-symmetric: for solvers that take such matrices, and the consistency tests).
///
/// A state of another solver (or of none, a fixed obstacle) is held fixed by each solve
/// (MechanicalOperations' foreign states): its blocks only enter the system that owns it.
template <class DataTypes1, class DataTypes2>
class PenalityContactForceField final : public BaseForceField, public RunSummaryProvider {
 public:
  using State1 = MechanicalState<DataTypes1>;
  using State2 = MechanicalState<DataTypes2>;

  Data<bool> d_geometricStiffness{this, "geometricStiffness", false,
                                  "Add to the stiffness the turn of the contact points' arms "
                                  "with their frames ([f]x [r]x on a frame's rotation block): "
                                  "the exact tangent, not symmetric."};
  Data<Vec3d> d_force{this,
                      "force",
                      Vec3d::Zero(),
                      "Output: the total force of the contacts on the second model's side at "
                      "the last force evaluation (N, minus that on the first), as the "
                      "constraint responses' force.",
                      {.output = true}};

  PenalityContactForceField(State1* state1, State2* state2) : m_state1(state1), m_state2(state2) {}

  /// This step's contacts (the vector keeps its capacity: no allocation once warm).
  std::vector<PenaltyContact>& contacts() { return m_contacts; }
  const std::vector<PenaltyContact>& contacts() const { return m_contacts; }

  /// The total force on side 2 at the last accumulateForce (minus that on side 1), and the
  /// contacts that pushed then.
  const Vec3d& lastForce() const { return m_lastForce; }
  int activeContacts() const { return m_active; }


  /// `stroma run`'s last lines: the contacts and the force at the end, the largest force.
  std::vector<std::string> runSummaryLines() const override;

  void accumulateForce(const MechanicalParams& mp, VecId f) override;
  void accumulateDForce(const MechanicalParams& mp, VecId df, VecId dx) override;
  void accumulateKMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                         const StateOffsets& offsets) override;
  double energy(const MechanicalParams& mp) const override;
  std::vector<BaseMechanicalState*> states() const override { return {m_state1, m_state2}; }

 private:
  double penetration(const PenaltyContact& c, const std::vector<typename DataTypes1::Coord>& x1,
                     const std::vector<typename DataTypes2::Coord>& x2) const;

  State1* m_state1;
  State2* m_state2;
  std::vector<PenaltyContact> m_contacts;
  Vec3d m_lastForce = Vec3d::Zero();
  int m_active = 0;

  double m_largestForce = 0, m_largestForceTime = 0;
};

}  // namespace stroma
