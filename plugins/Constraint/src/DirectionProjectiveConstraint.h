// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "AllowedMotion.h"
#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Lets points move only along `direction` (SOFA's DirectionProjectiveConstraint, formerly
/// ProjectDirectionConstraint): each point stays on the line through its rest position along
/// the direction. With d the unit direction and P = d d^T (AllowedMotion.h): forces, increments
/// and velocities of the points become P v, positions x0 + P (x - x0) (x0 the rest position).
/// A direction along a coordinate axis is exact in an assembled matrix (the two other axes'
/// rows are fixed); an oblique one is not (a warning at the first assembly, and the step's end
/// projection alone enforces it). A zero direction is an error; indices out of range are
/// reported and skipped.
class DirectionProjectiveConstraint final : public ProjectiveConstraint<Vec3Types> {
 public:
  Data<std::vector<unsigned>> d_indices{
      this, "indices", {}, "Indices of the points that move along the direction."};
  Data<Vec3d> d_direction{this, "direction", Vec3d(1, 0, 0),
                          "Direction of the allowed motion (any length but zero; normalized)."};
  Data<double> d_drawSize{this, "drawSize", 0.0, "Viewers only."};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (indices refer to points)."};

  void init() override;
  void reinit() override { init(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord& x, double time) override;
  void fixedRows(std::vector<std::size_t>& rows) const override;

 private:
  /// Checks the indices and the direction again when they changed (they may while running).
  void update();
  constraint::AllowedMotion m_motion;
  std::uint64_t m_checkedIndices = 0, m_checkedDirection = 0;
  mutable bool m_reportedAssembled = false;
};

}  // namespace stroma
