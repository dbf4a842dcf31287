// SPDX-License-Identifier: MIT
#include "MouseSpringForceField.h"

#include <string>

namespace stroma {

void MouseSpringForceField::init() {
  ForceField<Vec3Types>::init();
  if (mstate() && d_index.value() >= mstate()->size())
    msgError("index " + std::to_string(d_index.value()) + " is past the state's " +
                 std::to_string(mstate()->size()) + " points",
             "index");
}

void MouseSpringForceField::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                     const VecDeriv&) {
  const unsigned i = d_index.value();
  if (i < x.size()) f[i] += d_stiffness.value() * (d_target.value() - x[i]);
}

void MouseSpringForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                      const VecDeriv& dx) {
  const unsigned i = d_index.value();
  if (i < dx.size()) df[i] -= mp.kFactor * d_stiffness.value() * dx[i];
}

void MouseSpringForceField::addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                         std::size_t offset) {
  if (mp.kFactor == 0 || d_index.value() >= mstate()->size()) return;
  const std::size_t row = offset + 3 * std::size_t{d_index.value()};
  matrix.addBlock(row, row, -mp.kFactor * d_stiffness.value() * Eigen::Matrix3d::Identity());
}

double MouseSpringForceField::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  const unsigned i = d_index.value();
  return i < x.size() ? 0.5 * d_stiffness.value() * (x[i] - d_target.value()).squaredNorm() : 0.0;
}

}  // namespace stroma
