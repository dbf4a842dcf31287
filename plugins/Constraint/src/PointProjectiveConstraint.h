// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "AllowedMotion.h"
#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Puts points at `point` and keeps them there (SOFA's PointProjectiveConstraint, formerly
/// ProjectToPointConstraint): their forces, increments and velocities are zeroed (P = 0,
/// AllowedMotion.h) and their positions set to `point`, wherever they start; their rows and
/// columns of an assembled matrix become the identity. Indices out of range are reported and
/// skipped.
class PointProjectiveConstraint final : public ProjectiveConstraint<Vec3Types> {
 public:
  Data<std::vector<unsigned>> d_indices{
      this, "indices", {}, "Indices of the points put at `point`."};
  Data<Vec3d> d_point{this, "point", Vec3d::Zero(), "Where the points are put.", {.unit = "m"}};
  Data<bool> d_fixAll{this, "fixAll", false, "Put every point at `point`."};
  Data<double> d_drawSize{this, "drawSize", 0.0, "Viewers only."};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (indices refer to points)."};

  void init() override;
  void reinit() override { init(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord& x, double time) override;
  void fixedRows(std::vector<std::size_t>& rows) const override;

 private:
  template <class F>
  void forEachConstrained(std::size_t n, F&& f) const;
  /// Reports indices out of range once per new value of `indices`.
  void checkIndices();
  std::uint64_t m_checkedIndices = 0;
};

}  // namespace stroma
