// SPDX-License-Identifier: MIT
#pragma once

#include <utility>
#include <vector>

#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Attaches points of one state to points of another, one way (SOFA's
/// AttachProjectiveConstraint, formerly AttachConstraint): point indices2[k] of `object2`
/// follows point indices1[k] of `object1`. The followers' increments are zeroed (so the leaders
/// feel nothing: one way) and at the end of each step their positions and velocities are set
/// to their leaders'; in an assembled matrix their rows and columns become the identity. It
/// lives with both states under one solver, after the leaders are integrated; the followers
/// lag the leaders inside a step (they are held during the solve), as in SOFA.
///
/// `object1`/`object2` name a state or a node holding one (default: this node's). A pair with
/// constraintFactor 0 is released, 1 attached. Errors: lists of different lengths, indices out
/// of range, a factor other than 0 or 1, `twoWay` (SOFA's two-way attachment, where the leaders
/// also feel the followers, is not provided).
class AttachProjectiveConstraint final : public BaseProjectiveConstraint {
 public:
  using State = MechanicalState<Vec3Types>;

  Link<Base> l_object1{this, "object1",
                       "The state (or a node holding it) whose points lead (default: this "
                       "node's)."};
  Link<Base> l_object2{this, "object2",
                       "The state (or a node holding it) whose points follow (default: this "
                       "node's)."};
  Data<std::vector<unsigned>> d_indices1{
      this, "indices1", {}, "Indices of the leading points in object1 (nbPairs)."};
  Data<std::vector<unsigned>> d_indices2{
      this, "indices2", {}, "Indices of the following points in object2 (nbPairs)."};
  Data<bool> d_twoWay{this, "twoWay", false,
                      "SOFA's two-way attachment (the leaders feel the followers): not provided, "
                      "an error when set."};
  Data<std::vector<double>> d_constraintFactor{
      this,
      "constraintFactor",
      {},
      "Per pair: 1 attached, 0 released (nbPairs; empty: all attached).",
      {.min = 0.0, .max = 1.0}};

  void init() override;
  void bwdInit() override;
  void reinit() override {
    init();
    bwdInit();
  }

  void constrainResponse(VecId dx) override;
  void constrainVelocity(VecId v, double time) override;
  void constrainPosition(VecId x, double time) override;
  void fixedRows(std::vector<std::size_t>& rows) const override;
  BaseMechanicalState* state() const override { return m_followers; }

  /// The attached pairs (leader in object1, follower in object2), checked.
  const std::vector<std::pair<unsigned, unsigned>>& pairs() const { return m_pairs; }

 private:
  State* m_leaders = nullptr;
  State* m_followers = nullptr;
  std::vector<std::pair<unsigned, unsigned>> m_pairs;
};

}  // namespace stroma
