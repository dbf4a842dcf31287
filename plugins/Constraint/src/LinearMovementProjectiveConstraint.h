// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Moves points or rigid frames along a piecewise-linear trajectory (SOFA's
/// LinearMovementProjectiveConstraint). `movements` holds one displacement per key time; between
/// two key times the displacement is interpolated linearly, and the points are placed at
///   x(t) = x0 + m(t)          (relativeMovements, the default; x0 = positions at init)
///   x(t) = m(t)               (absolute),
/// For rigid frames a movement is "dx dy dz ax ay az": a translation of the centre and Euler
/// angles (rotation R = Rz(az) Ry(ay) Rx(ax), SOFA's convention), the orientation being
/// q0 * slerp(q(m_k), q(m_k+1), s).
///
/// A step from t to t + h is constrained when t0 <= t < tN (first and last key times), as in
/// SOFA: before t0 and from tN on, the points are free. During a constrained step
/// projectResponse zeroes the points' increments, projectPosition puts them at x(t + h) (the
/// end of the step), and projectVelocity gives them the mean velocity (x(t + h) - x(t)) / h,
/// so that positions and velocities agree.
template <class DataTypes>
class LinearMovementProjectiveConstraint final : public ProjectiveConstraint<DataTypes> {
 public:
  using typename ProjectiveConstraint<DataTypes>::Coord;
  using typename ProjectiveConstraint<DataTypes>::Deriv;
  using typename ProjectiveConstraint<DataTypes>::VecCoord;
  using typename ProjectiveConstraint<DataTypes>::VecDeriv;

  Data<std::vector<unsigned>> d_indices{
      this, "indices", {0}, "Indices of the moved points (SOFA's default: 0)."};
  Data<std::vector<double>> d_keyTimes{
      this, "keyTimes", {}, "Key times, in increasing order (nbKeys).", {.unit = "s"}};
  Data<VecDeriv> d_movements{this,
                             "movements",
                             {},
                             "Displacement at each key time (nbKeys x 3 for points; nbKeys x 6 "
                             "'dx dy dz ax ay az' for rigid frames, angles in radians).",
                             {.unit = "m"}};
  Data<bool> d_relativeMovements{this, "relativeMovements", true,
                                 "Movements are relative to the positions at init; else "
                                 "absolute positions."};
  Data<bool> d_showMovement{this, "showMovement", false, "Viewers only."};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (indices refer to points)."};

  void init() override;
  void reinit() override { init(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord& x, double time) override;
  void fixedRows(std::vector<std::size_t>& rows) const override;

  /// Where point `index` is at time t (t clamped to the key times). Requires init().
  Coord positionAt(std::size_t index, double t) const;

 private:
  /// True when a step that starts at t is constrained (t0 <= t < tN).
  bool isActive(double t) const;
  template <class F>
  void forEachMoved(std::size_t n, F&& f) const;

  VecCoord m_x0;  ///< positions of the moved points at init (indexed like the state)
};

}  // namespace stroma
