// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include "ArticulatedMapping.h"
#include "simulation/Mass.h"

namespace stroma {

/// The masses of the links of an articulated body, in its joint coordinates q (Vec1d): the
/// links' masses, centers of mass and inertias give the joint-space mass matrix
///   M(q) = sum_i m_i Jv_i^T Jv_i + Jw_i^T (R_i I_i R_i^T) Jw_i
/// (Jv_i, Jw_i: linear velocity of link i's center of mass and its angular velocity per unit
/// qdot, from the mapping's kinematic tree), gravity's generalized force sum_i m_i Jv_i^T g,
/// and the velocity-dependent forces of the moving mass matrix (Coriolis and centrifugal), from
/// Lagrange's equations
///   M qddot = tau_gravity - (dM/dt qdot - 1/2 d(qdot^T M qdot)/dq) + other forces.
/// Putting masses on the mapped link frames instead (UniformMass Rigid3d, J^T M J through the
/// mapping) would lose the last term, and with it the conservation of energy.
///
/// The derivatives of M and of the gravity force in q are central differences of the exact
/// expressions (step 1e-6 rad or m): O(1e-12) relative. The Coriolis force is explicit in the
/// implicit solvers (no B matrix); gravity's K = d tau_gravity / dq is assembled.
class ArticulatedBodyMass final : public Mass<Vec1Types> {
 public:
  Link<ArticulatedMapping> l_mapping{this, "mapping",
                                     "The ArticulatedMapping whose kinematic tree places the "
                                     "links."};
  Data<std::vector<double>> d_linkMasses{this, "linkMasses", {},
                                         "Mass of each link (nbLinks); 0 for a link without "
                                         "mass.",
                                         {.unit = "kg", .min = 0.0}};
  Data<std::vector<Vec3d>> d_centersOfMass{this, "centersOfMass", {},
                                           "Center of mass of each link in its frame (nbLinks x "
                                           "3); default: the link frame's origin.",
                                           {.unit = "m"}};
  Data<std::vector<double>> d_inertias{
      this, "inertias", {},
      "Inertia of each link about its center of mass, in the link's frame (nbLinks x 'ixx ixy "
      "ixz iyy iyz izz', URDF's order); default: zero.",
      {.unit = "kg m^2"}};

  Data<std::vector<double>> d_armature{
      this, "armature", {},
      "Rotor inertia reflected at each joint (nbJoints, or one for all), added to M's diagonal "
      "(MuJoCo's armature): URDF has none; it also keeps light distal links from making M "
      "stiff.",
      {.unit = "kg m^2"}};

  void init() override;

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  void addMDx(VecDeriv& f, const VecDeriv& dx, double factor) override;
  void accFromF(VecDeriv& a, const VecDeriv& f) override;
  void addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) override;
  double kineticEnergy(const VecDeriv& v) const override;
  bool isDiagonal() const override { return false; }

  /// M(q), dofCount x dofCount.
  Eigen::MatrixXd computeMassMatrix(const VecCoord& q) const;
  /// Gravity's generalized force at q.
  Eigen::VectorXd computeGravityForce(const VecCoord& q) const;
  /// The Coriolis and centrifugal generalized force at (q, qdot) (the right-hand side's share).
  Eigen::VectorXd computeVelocityForce(const VecCoord& q, const VecDeriv& qdot) const;

 private:
  bool ready() const;
  const Eigen::MatrixXd& massAtCurrentPosition() const;
  Eigen::MatrixXd computeGravityStiffness(const VecCoord& q) const;

  std::vector<Mat3d> m_inertias;  // body frame, kg m^2
  mutable VecCoord m_cachedQ;
  mutable Eigen::MatrixXd m_cachedM;
};

}  // namespace stroma
