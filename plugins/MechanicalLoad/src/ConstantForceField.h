// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/ForceField.h"

namespace stroma {

/// Constant forces on points (SOFA's ConstantForceField): one force per index (`forces`), the
/// same force on each index (`force`), or a total force spread evenly (`totalForce`).
class ConstantForceField final : public ForceField<Vec3Types> {
 public:
  Data<std::vector<unsigned>> d_indices{this, "indices", {},
                                        "Points that receive a force (default: all)."};
  Data<std::vector<Vec3d>> d_forces{this, "forces", {}, "One force per index.", {.unit = "N"}};
  Data<Vec3d> d_force{this, "force", Vec3d::Zero(), "The same force on every index.",
                      {.unit = "N"}};
  Data<Vec3d> d_totalForce{this, "totalForce", Vec3d::Zero(),
                           "A total force, spread evenly over the indices.", {.unit = "N"}};
  Data<double> d_showArrowSize{this, "showArrowSize", 0.0, "Viewers only."};

  void init() override;

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
