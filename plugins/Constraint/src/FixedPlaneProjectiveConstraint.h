// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "AllowedMotion.h"
#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Zeroes the displacement of points along `direction` (SOFA's FixedPlaneProjectiveConstraint,
/// formerly FixedPlaneConstraint): each point keeps its coordinate d.x (d the unit direction)
/// and moves freely in the plane normal to d through where it starts. With P = I - d d^T
/// (AllowedMotion.h) forces, increments and velocities of the points become P v, and positions
/// x0 + P (x - x0) (x0 the rest position): the displacement along d stays zero even when an
/// assembled solve could not hold the projection.
///
/// The points are `indices`; when none is given, the points whose rest position lies between
/// `dmin` and `dmax` along d (dmin <= d.x <= dmax, bounds included), selected at init and
/// written to `indices`. A direction along a coordinate axis is exact in an assembled matrix
/// (that axis's rows are fixed); an oblique one is not (a warning at the first assembly: the
/// linear solve is then unconstrained along d, and the end of the step projects). Errors: a zero
/// direction, dmin > dmax, indices out of range (reported and skipped).
class FixedPlaneProjectiveConstraint final : public ProjectiveConstraint<Vec3Types> {
 public:
  Data<std::vector<unsigned>> d_indices{
      this,
      "indices",
      {},
      "Indices of the constrained points; empty: those between dmin and dmax along the "
      "direction (written back here)."};
  Data<Vec3d> d_direction{this, "direction", Vec3d(0, 0, 1),
                          "Direction along which the displacement is zero (any length but "
                          "zero; normalized)."};
  Data<double> d_dmin{this,
                      "dmin",
                      0.0,
                      "Lowest distance d.x of a selected point (when `indices` is empty).",
                      {.unit = "m"}};
  Data<double> d_dmax{this,
                      "dmax",
                      0.0,
                      "Highest distance d.x of a selected point (when `indices` is empty).",
                      {.unit = "m"}};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (indices refer to points)."};

  void init() override;
  void reinit() override { init(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord& x, double time) override;
  void fixedRows(std::vector<std::size_t>& rows) const override;

  const constraint::AllowedMotion& motion() const { return m_motion; }

 private:
  /// Selects the points between dmin and dmax along the direction into `indices`.
  void selectAlongDirection(const Vec3d& d);
  /// Reports indices out of range once per new value of `indices`.
  void checkIndices();
  constraint::AllowedMotion m_motion;
  bool m_selectsAlongDirection = false;  ///< `indices` was empty at the first init
  std::uint64_t m_checkedIndices = 0;
  mutable bool m_reportedAssembled = false;
};

}  // namespace stroma
