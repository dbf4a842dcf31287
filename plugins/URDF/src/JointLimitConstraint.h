// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Joint limits as a projective clamp on joint values (Vec1d): after each step, a value
/// beyond its range [lower, upper] is put back on the bound, and its velocity, if it points
/// out of the range, is set to zero (an inelastic stop). A joint pushed against its limit
/// thus stays on it to round-off; it leaves the limit as soon as the forces pull it inward.
/// The stop's force is not computed (it is not a Lagrange multiplier): the joint torques of a
/// JointActuatorForceField are those of the drive, not the limit's reaction.
class JointLimitConstraint final : public ProjectiveConstraint<Vec1Types> {
 public:
  Data<std::vector<unsigned>> d_indices{this, "indices", {}, "Limited joint values (n)."};
  Data<std::vector<double>> d_lower{this, "lower", {}, "Lower bound of each (n), rad or m."};
  Data<std::vector<double>> d_upper{this, "upper", {}, "Upper bound of each (n), rad or m."};

  void init() override;
  void projectResponse(VecDeriv&) override {}
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord& x, double time) override;
  void fixedRows(std::vector<std::size_t>&) const override {}

 private:
  bool m_ready = false;
};

}  // namespace stroma
