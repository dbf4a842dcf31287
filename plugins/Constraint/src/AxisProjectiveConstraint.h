// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "AllowedMotion.h"
#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// What the plane, line and direction projections share (PlaneProjectiveConstraint,
/// LineProjectiveConstraint, DirectionProjectiveConstraint): points `indices` whose motion is
/// restricted by one vector (a plane's normal, a line's direction) through the projector of
/// AllowedMotion.h. Forces, increments and velocities of the points become P v; positions go
/// back on the allowed set (each class says through which point). An axis-aligned vector is
/// exact in an assembled matrix (fixed rows); an oblique one warns at the first assembly (the
/// step's end projection alone enforces it). A zero vector is an error and leaves the points
/// free; indices out of range are reported and skipped. Both are checked again when they change.
class AxisProjectiveConstraint : public ProjectiveConstraint<Vec3Types> {
 public:
  Data<std::vector<unsigned>> d_indices;

  void init() override;
  void reinit() override { init(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord& x, double time) override;
  void fixedRows(std::vector<std::size_t>& rows) const override;

  const constraint::AllowedMotion& motion() const { return m_motion; }

 protected:
  explicit AxisProjectiveConstraint(const char* indicesHelp)
      : d_indices{this, "indices", {}, indicesHelp} {}
  /// The Data of the vector (normal or direction), and the motion its unit vector allows.
  virtual const Data<Vec3d>& axis() const = 0;
  virtual constraint::AllowedMotion motionAlong(const Vec3d& unit) const = 0;
  /// Puts the points back on the allowed set (through an origin, or their rest positions).
  virtual void projectPoints(VecCoord& x) = 0;

 private:
  void update();
  constraint::AllowedMotion m_motion;
  std::uint64_t m_checkedIndices = 0, m_checkedAxis = 0;
  mutable bool m_reportedAssembled = false;
};

}  // namespace stroma
