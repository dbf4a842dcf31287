// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/ForceField.h"

namespace stroma {

/// Constant forces on points (Vec3d, Vec2d, Vec1d: a force has as many components as a point)
/// or rigid frames (SOFA's ConstantForceField): one force per index
/// (`forces`), the same force on each index (`force`), or a total force spread evenly
/// (`totalForce`). For rigid frames a force is "fx fy fz tx ty tz" (force at the centre and
/// torque, world frame). Energy: -f.x for the forces (torques do no work that a potential of the
/// positions can express, and are left out of it).
template <class DataTypes>
class ConstantForceField final : public ForceField<DataTypes> {
 public:
  using Deriv = typename DataTypes::Deriv;
  using typename ForceField<DataTypes>::VecCoord;
  using typename ForceField<DataTypes>::VecDeriv;

  Data<std::vector<unsigned>> d_indices{
      this, "indices", {}, "Points that receive a force (default: all)."};
  Data<VecDeriv> d_forces{this, "forces", {}, "One force per index.", {.unit = "N"}};
  Data<Deriv> d_force{
      this, "force", DataTypes::zeroDeriv(), "The same force on every index.", {.unit = "N"}};
  Data<Deriv> d_totalForce{this,
                           "totalForce",
                           DataTypes::zeroDeriv(),
                           "A total force, spread evenly over the indices.",
                           {.unit = "N"}};
  Data<double> d_showArrowSize{this, "showArrowSize", 0.0, "Viewers only."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams&, VecDeriv&, const VecDeriv&) override {}
  void addKToMatrix(const MechanicalParams&, MatrixAccumulator&, std::size_t) override {}
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

 private:
  template <class F>
  void forEachForce(std::size_t n, F&& f) const;
};

}  // namespace stroma
