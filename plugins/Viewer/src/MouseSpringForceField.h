// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/ForceField.h"

namespace stroma {

/// The spring of the viewer's mouse interaction: it pulls one point of a Vec3d state toward a
/// target that follows the mouse. The viewer adds it to the picked state's node when a drag
/// starts and removes it on release; no scene names it.
///
///   E = k/2 |x_i - t|^2,   f_i = k (t - x_i),   K = df/dx = -k I on the 3x3 block (i, i)
///
/// with k the stiffness (N/m), i the index and t the target (m). addForce, addDForce and
/// addKToMatrix agree, so that explicit and implicit solvers, matrix-free or assembled, all see
/// the same spring; a spring on a mapped state reaches the independent one through the mapping
/// like any force field there.
class MouseSpringForceField final : public ForceField<Vec3Types> {
 public:
  Data<unsigned> d_index{this, "index", 0u, "The pulled point of the state."};
  Data<Vec3d> d_target{this, "target", Vec3d::Zero(),
                       "Where the point is pulled to: the mouse at the picked depth.",
                       {.unit = "m"}};
  Data<double> d_stiffness{this, "stiffness", 1000.0, "Stiffness of the spring.",
                           {.unit = "N/m", .min = 0.0}};

  void init() override;

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;
};

}  // namespace stroma
