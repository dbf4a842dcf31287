// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Fixes some directions of points or rigid frames (SOFA's PartialFixedProjectiveConstraint):
/// `fixedDirections` holds one flag per derivative component (x y z for points; x y z and the
/// three rotations for rigid frames). The fixed components of forces, increments and velocities
/// are zeroed, and their rows and columns of an assembled matrix become the identity; the free
/// ones move as usual.
template <class DataTypes>
class PartialFixedProjectiveConstraint final : public ProjectiveConstraint<DataTypes> {
 public:
  using typename ProjectiveConstraint<DataTypes>::VecCoord;
  using typename ProjectiveConstraint<DataTypes>::VecDeriv;

  Data<std::vector<unsigned>> d_indices{this, "indices", {}, "Indices of the constrained points."};
  Data<bool> d_fixAll{this, "fixAll", false, "Constrain every point."};
  Data<std::vector<int>> d_fixedDirections{
      this,
      "fixedDirections",
      {},
      "1 for each fixed derivative component, 0 for a free one (3 flags for points, 6 for "
      "rigid frames); empty: all fixed.",
      {.min = 0.0, .max = 1.0}};
  Data<bool> d_projectVelocity{this, "projectVelocity", false,
                               "SOFA option, accepted: velocities are always projected."};
  Data<bool> d_showObject{this, "showObject", true, "Viewers only."};
  Data<double> d_drawSize{this, "drawSize", 0.0, "Viewers only."};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (indices refer to points)."};

  void init() override;
  void reinit() override { init(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord&, double) override {}
  void fixedRows(std::vector<std::size_t>& rows) const override;

 private:
  /// Zeroes the fixed components of every constrained derivative.
  void project(VecDeriv& v) const;
  bool isFixed(std::size_t component) const;
  template <class F>
  void forEachConstrained(std::size_t n, F&& f) const;
};

}  // namespace stroma
