// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/ForceField.h"

namespace hardening {

/// Pulls every point back to its rest position with a hardening spring: with u = x - x_rest,
///   energy  E = k |u|^2 / 2 + c |u|^4 / 4,
///   force   f = -(k + c |u|^2) u,
///   tangent K = df/dx = -(k + c |u|^2) I - 2 c u u^T   (3x3 per point, symmetric).
/// A force field of a third-party plugin: it only uses Stroma's installed headers, and
/// implements the four methods every force field has (force, its derivative applied to an
/// increment, the assembled tangent, the energy), so that implicit, static and explicit
/// solvers can all use it.
class HardeningAnchorForceField final : public stroma::ForceField<stroma::Vec3Types> {
 public:
  stroma::Data<double> d_stiffness{
      this, "stiffness", 1.0, "Linear stiffness k.", {.unit = "N/m", .min = 0}};
  stroma::Data<double> d_hardening{
      this, "hardening", 0.0, "Cubic coefficient c.", {.unit = "N/m^3", .min = 0}};

  void init() override;

  void addForce(const stroma::MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const stroma::MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const stroma::MechanicalParams& mp, stroma::MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const stroma::MechanicalParams& mp, const VecCoord& x) const override;

 private:
  /// The 3x3 tangent block of point i at its current position.
  Eigen::Matrix3d tangent(const stroma::Vec3d& u) const;
  VecCoord m_rest;
  VecCoord m_current;  // the positions of the last addForce, where addDForce linearizes
};

}  // namespace hardening
