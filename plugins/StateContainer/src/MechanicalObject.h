// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <vector>

#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"

namespace stroma {

/// The state vectors of a set of points (Vec3d; Vec2d and Vec1d in a plane or on a line) or rigid
/// frames (Rigid3d), SOFA's attributes. The initial transform (translation, rotation, scale) is
/// applied in 3D to points of fewer coordinates, the missing ones 0, which then keep their
/// first 1 or 2 coordinates, as in SOFA.
template <class DataTypes>
class MechanicalObject final : public MechanicalState<DataTypes> {
 public:
  using Coord = typename DataTypes::Coord;
  using Deriv = typename DataTypes::Deriv;
  using VecCoord = std::vector<Coord>;
  using VecDeriv = std::vector<Deriv>;
  using Base::msgError;
  using Base::msgWarning;

  Data<VecCoord> d_position{this, "position", {}, "Positions (size x coordinates).",
                            {.unit = "m"}};
  Data<VecDeriv> d_velocity{this, "velocity", {}, "Velocities (size x derivatives).",
                            {.unit = "m/s"}};
  Data<VecDeriv> d_force{this, "force", {}, "Forces accumulated during a step.", {.unit = "N"}};
  Data<VecDeriv> d_externalForce{this, "externalForce", {}, "Forces applied from outside.",
                                 {.unit = "N"}};
  Data<VecDeriv> d_derivX{this, "derivX", {}, "Position increment (dx) of the last solve.",
                          {.unit = "m"}};
  Data<VecDeriv> d_constraintForce{this, "constraintForce", {},
                                   "Output: the force of the Lagrangian constraints and contacts "
                                   "on each degree of freedom at the last step (H^T lambda; "
                                   "Rigid3d: force, then torque about the frame's origin), "
                                   "what a haptic device renders.",
                                   {.unit = "N", .output = true}};
  Data<VecCoord> d_restPosition{this, "rest_position", {},
                                "Rest positions; the initial positions when not given.",
                                {.unit = "m"}};
  Data<VecCoord> d_freePosition{this, "free_position", {}, "Free-motion positions.", {.unit = "m"}};
  Data<VecDeriv> d_freeVelocity{this, "free_velocity", {}, "Free-motion velocities.",
                                {.unit = "m/s"}};
  Data<VecCoord> d_resetPosition{this, "reset_position", {},
                                 "Positions restored by a reset; the initial ones when not given.",
                                 {.unit = "m"}};
  Data<int> d_size{this, "size", 0,
                   "Number of degrees of freedom when no position is given (set at the origin).",
                   {.min = 0.0, .max = 1e7}};
  Data<Vec3d> d_translation{this, "translation", Vec3d::Zero(),
                            "Translation applied to the initial positions.", {.unit = "m"}};
  Data<Vec3d> d_rotation{this, "rotation", Vec3d::Zero(),
                         "Rotation of the initial positions, about x then y then z.",
                         {.unit = "deg"}};
  Data<Vec3d> d_scale3d{this, "scale3d", Vec3d::Ones(), "Scale of the initial positions."};
  Data<double> d_scale{this, "scale", 1.0, "Uniform scale of the initial positions."};
  Data<double> d_dx{this, "dx", 0.0, "Translation along x (added to translation).", {.unit = "m"}};
  Data<double> d_dy{this, "dy", 0.0, "Translation along y (added to translation).", {.unit = "m"}};
  Data<double> d_dz{this, "dz", 0.0, "Translation along z (added to translation).", {.unit = "m"}};
  Data<double> d_rx{this, "rx", 0.0, "Rotation about x (added to rotation).", {.unit = "deg"}};
  Data<double> d_ry{this, "ry", 0.0, "Rotation about y (added to rotation).", {.unit = "deg"}};
  Data<double> d_rz{this, "rz", 0.0, "Rotation about z (added to rotation).", {.unit = "deg"}};
  Data<double> d_restScale{this, "restScale", 1.0, "Scale of the rest positions."};
  Data<bool> d_useMask{this, "useMask", false, "SOFA option, accepted and without effect."};
  Data<std::vector<double>> d_bbox{this, "bbox", {}, "Bounding box (viewers only)."};
  Data<bool> d_showObject{this, "showObject", false, "Draw the points (viewers only)."};
  Data<double> d_showObjectScale{this, "showObjectScale", 1.0, "Point size (viewers only)."};
  Data<bool> d_showIndices{this, "showIndices", false, "Draw indices (viewers only)."};
  Data<double> d_showIndicesScale{this, "showIndicesScale", 1.0, "Index size (viewers only)."};
  Data<int> d_drawMode{this, "drawMode", 0, "Point drawing mode (viewers only)."};
  Data<std::vector<double>> d_showColor{this, "showColor", {}, "Point color (viewers only)."};

  std::size_t size() const override { return d_position.value().size(); }
  void copyPositions(std::vector<double>& out) const override;
  void copyVelocities(std::vector<double>& out) const override;

  void init() override;

  // State vectors by id (MechanicalState).
  const VecCoord& readCoord(VecId v) const override;
  VecCoord& writeCoord(VecId v) override;
  const VecDeriv& readDeriv(VecId v) const override;
  VecDeriv& writeDeriv(VecId v) override;
  void vAlloc(VecId v) override;
  void vFree(VecId v) override;
  void vOp(VecId v, VecId a, VecId b, double f) override;
  double vDot(VecId a, VecId b) const override;
  double vMaxAbs(VecId a, std::size_t& where) const override;
  void copyToGlobal(VecId v, Eigen::Ref<Eigen::VectorXd> g, std::size_t offset) const override;
  void copyFromGlobal(VecId v, const Eigen::Ref<const Eigen::VectorXd>& g,
                      std::size_t offset) override;

 private:
  Data<VecCoord>* coordData(int index);
  Data<VecDeriv>* derivData(int index);
  /// writeDeriv for a known size() (n), read once per vector operation.
  VecDeriv& derivOfSize(VecId v, std::size_t n);
  // Temporaries of solvers, by id - VecId::kFirstTemporary. Kept between steps (capacity
  // reused), so that a step allocates nothing after the first.
  mutable std::vector<std::unique_ptr<VecCoord>> m_tempCoords;
  mutable std::vector<std::unique_ptr<VecDeriv>> m_tempDerivs;
  mutable std::vector<double> m_scratch;
};

}  // namespace stroma
