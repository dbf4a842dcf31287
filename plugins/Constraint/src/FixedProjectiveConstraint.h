// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Fixes points or rigid frames (SOFA's FixedProjectiveConstraint, formerly FixedConstraint):
/// their forces, increments and velocities are zeroed, so they stay where they start; their
/// rows and columns of an assembled matrix become the identity. Changing `indices` while
/// running takes effect at the next step.
template <class DataTypes>
class FixedProjectiveConstraint final : public ProjectiveConstraint<DataTypes> {
 public:
  using typename ProjectiveConstraint<DataTypes>::VecCoord;
  using typename ProjectiveConstraint<DataTypes>::VecDeriv;

  Data<std::vector<unsigned>> d_indices{this, "indices", {}, "Indices of the fixed points."};
  Data<bool> d_fixAll{this, "fixAll", false, "Fix every point."};
  Data<bool> d_activateProjectVelocity{this, "activate_projectVelocity", false,
                                       "SOFA option, accepted: velocities are always zeroed."};
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
  template <class F>
  void forEachFixed(std::size_t n, F&& f) const;
  /// Reports indices out of range once per new value of `indices` (they may change while
  /// the simulation runs); the projections skip them.
  void checkIndices();
  std::uint64_t m_checkedIndices = 0;
};

}  // namespace stroma
