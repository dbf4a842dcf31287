// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/ForceField.h"

namespace stroma {

/// A penalty plane (SOFA's PlaneForceField): points, or rigid frame centres, below the plane
/// x.n = d are pushed back along n. With delta = x.n - d (n the unit normal; a normal given
/// with another length is normalized and d divided by it, so the plane stays the same):
///   f = -k delta n + c delta v        for delta < 0 (every point when bilateral)
/// The damping term, proportional to the depth as in Hunt and Crossley (1975), vanishes at
/// first contact, so the force has no jump; like SOFA's it damps the whole velocity (tangential
/// motion included). Energy: k delta^2 / 2.
/// Derivatives, for the points below the plane at the positions mp.x: K = df/dx = -k n n^T
/// (the damping's position derivative c v n^T is left out, which keeps K symmetric as CG
/// needs), B = df/dv = c delta I. A point resting on a floor under its weight m g sits at the
/// depth m |g.n| / k.
template <class DataTypes>
class PlaneForceField final : public ForceField<DataTypes> {
 public:
  using typename ForceField<DataTypes>::VecCoord;
  using typename ForceField<DataTypes>::VecDeriv;

  Data<Vec3d> d_normal{this, "normal", Vec3d(0, 1, 0),
                       "Normal of the plane, pointing to the free side."};
  Data<double> d_d{this, "d", 0.0, "The plane is the points x with x.normal = d.", {.unit = "m"}};
  Data<double> d_stiffness{
      this, "stiffness", 500.0, "Penalty stiffness k.", {.unit = "N/m", .min = 0.0}};
  Data<double> d_damping{this,
                         "damping",
                         5.0,
                         "Damping c, times the depth (force c * depth * velocity).",
                         {.unit = "N s/m^2", .min = 0.0}};
  Data<bool> d_bilateral{this, "bilateral", false,
                         "Act on the points on both sides (a spring to the plane)."};
  Data<bool> d_showPlane{this, "showPlane", false, "Viewers only."};
  Data<Vec4d> d_planeColor{this, "planeColor", Vec4d(0, 0.5, 0.2, 1), "Viewers only."};
  Data<double> d_showPlaneSize{this, "showPlaneSize", 10.0, "Viewers only."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

 private:
  /// f(i, delta) for every point i in contact at positions x.
  template <class F>
  void forEachContact(const VecCoord& x, F&& f) const;
  Vec3d unitNormal() const;
};

}  // namespace stroma
