// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "KinematicTree.h"
#include "core/StateTypes.h"
#include "simulation/Mapping.h"

namespace stroma {

/// Frames of the links of an articulated body from its joint values (the role of SOFA's
/// ArticulatedSystemMapping, with URDF's description of the joints; Vec1d -> Rigid3d): the
/// input holds one value per moving joint (an angle in rad or a length in m), the output one
/// frame per link (or per `outputLinks` entry, shifted by `outputOffsets`), by the forward
/// kinematics of KinematicTree.h.
///
/// Velocities are as the rigid state keeps them: the linear velocity of the frame's center and
/// the angular velocity, both in world coordinates. A revolute joint j with world axis a_j
/// through p_j moves output frame k (center c_k) on its chain by
///   v = a_j x (c_k - p_j),  w = a_j   per unit qdot_j;
/// a prismatic one by v = a_j, w = 0. J^T gives the joint torque a_j . (r x F + T) and the
/// joint force a_j . F. The change of J with q (its geometric stiffness) is left out of the
/// linearized system, as RigidMapping does.
class ArticulatedMapping final : public Mapping<Vec1Types, Rigid3Types> {
 public:
  Data<std::vector<int>> d_parents{this, "parents", {},
                                   "Parent link of each link (nbLinks); -1 for the base link "
                                   "(the first), else an earlier link."};
  Data<std::vector<std::string>> d_jointTypes{
      this, "jointTypes", {},
      "Type of the joint of each link (nbLinks): fixed, revolute, continuous or prismatic; the "
      "base link's is fixed."};
  Data<std::vector<RigidCoord3>> d_origins{
      this, "origins", {},
      "Frame of each link's joint in its parent link's frame (nbLinks x 'x y z qx qy qz qw')",
      {.unit = "m"}};
  Data<std::vector<Vec3d>> d_axes{this, "axes", {},
                                  "Axis of each link's joint in the joint frame (nbLinks x 3); "
                                  "default z."};
  Data<std::vector<int>> d_mimic{
      this, "mimic", {},
      "Per link (nbLinks), the link whose joint value its joint follows (URDF's mimic joints: "
      "no value of their own), or -1; default: none."};
  Data<std::vector<double>> d_mimicMultipliers{
      this, "mimicMultipliers", {}, "Per link (nbLinks): q = multiplier * q_source + offset."};
  Data<std::vector<double>> d_mimicOffsets{this, "mimicOffsets", {},
                                           "Per link (nbLinks): the offset (rad or m)."};
  Data<RigidCoord3> d_base{this, "base", RigidCoord3{},
                           "World frame of the base link ('x y z qx qy qz qw').", {.unit = "m"}};
  Data<std::vector<unsigned>> d_outputLinks{this, "outputLinks", {},
                                            "Link of each output frame (nbOutput); default: one "
                                            "frame per link."};
  Data<std::vector<RigidCoord3>> d_outputOffsets{
      this, "outputOffsets", {},
      "Each output frame in its link's frame (nbOutput x 'x y z qx qy qz qw'); default: the "
      "link's frame.",
      {.unit = "m"}};

  void init() override;

  void apply(OutVecCoord& out, const InVecCoord& in) override;
  void applyJ(OutVecDeriv& out, const InVecDeriv& in) override;
  void applyJT(InVecDeriv& in, const OutVecDeriv& out) override;
  /// nbOutput*6 x nbJointValues, at the input's current positions.
  const Eigen::SparseMatrix<double>& jacobian() override;

  const KinematicTree& tree() const { return m_tree; }

 private:
  bool setUp();
  /// J at joint values q into m_J.
  void computeJacobian(const InVecCoord& q);

  KinematicTree m_tree;
  std::vector<unsigned> m_outputLinks;
  std::vector<RigidCoord3> m_outputOffsets;
  std::vector<RigidCoord3> m_linkFrames;
  std::vector<RigidDeriv3> m_columns;
  Eigen::SparseMatrix<double> m_J;
  std::vector<Eigen::Triplet<double>> m_triplets;
  bool m_ready = false;
};

/// The joint type of a name (fixed, revolute, continuous, prismatic); false when unknown.
bool jointTypeFromName(const std::string& name, JointType& type);

}  // namespace stroma
