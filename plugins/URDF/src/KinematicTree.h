// SPDX-License-Identifier: MIT
// Forward kinematics of a tree of rigid links connected by one-degree-of-freedom joints, in
// reduced coordinates (one value per moving joint), and its Jacobian. Free of components: the
// articulated mapping and the articulated mass wire it to states and Data.
//
// Link i (i > 0) hangs from link parent[i] < i through its joint: the joint frame is placed by
// `origin` in the parent link's frame, and the joint moves the child link in that frame by
//   revolute (and continuous): a rotation by q about `axis` (a unit vector),
//   prismatic: a translation by q along `axis`,
//   fixed: nothing (no value in q).
// So the world frame of link i is T_i = T_parent * origin * motion(q). Link 0 is the base, at
// the tree's `base` frame. This is URDF's convention (its joint's origin, axis and type).
#pragma once

#include <string>
#include <vector>

#include "core/Types.h"

namespace stroma {

enum class JointType { fixed, revolute, prismatic };

struct KinematicJoint {
  int parent = -1;           ///< parent link, < the child's index; -1 for the base link
  RigidCoord3 origin;        ///< joint frame in the parent link's frame
  Vec3d axis = Vec3d::UnitZ();
  JointType type = JointType::fixed;
  int dof = -1;              ///< index in q, -1 for a fixed joint
  /// URDF's mimic joint: the link whose joint value this one follows, as multiplier * q +
  /// offset (no value of its own in q); -1 for an independent joint.
  int mimic = -1;
  double multiplier = 1;
  double offset = 0;
};

/// The joint (of a link, its parent and origin) and each link's world frame.
class KinematicTree {
 public:
  /// One joint per link; joints[0] is the base link's (fixed, parent -1). Returns false with
  /// `error` when a parent is not an earlier link, an axis is zero or a mimic joint follows no
  /// independent moving joint. Numbers the independent moving joints' values in link order; a
  /// mimic joint takes the number of the joint it follows.
  bool setJoints(std::vector<KinematicJoint> joints, std::string& error);
  void setBase(const RigidCoord3& base) { m_base = base; }

  std::size_t linkCount() const { return m_joints.size(); }
  std::size_t dofCount() const { return m_dofCount; }
  const std::vector<KinematicJoint>& joints() const { return m_joints; }

  /// World frames of every link at joint values q (dofCount values).
  void computeFrames(const std::vector<Vec1d>& q, std::vector<RigidCoord3>& frames) const;

  /// Velocity (linear of the point `point`, and angular, world coordinates) of a point fixed
  /// to link `link`, per unit speed of each joint value: column j is the 6-vector
  /// [v; w] for qdot = e_j. `frames` are computeFrames' at the same q. Fills `columns`
  /// (dofCount entries, zero for joints not on the link's chain; a mimic joint adds its
  /// multiplier times its motion to its source's column).
  void computePointJacobian(const std::vector<RigidCoord3>& frames, int link, const Vec3d& point,
                            std::vector<RigidDeriv3>& columns) const;

  /// The joints on the chain from the base to `link`, the link's own joint first.
  template <class F>
  void forEachMovingJointOnChain(int link, F&& f) const {
    for (int i = link; i > 0; i = m_joints[i].parent)
      if (m_joints[i].dof >= 0) f(i);
  }

 private:
  std::vector<KinematicJoint> m_joints;
  std::size_t m_dofCount = 0;
  RigidCoord3 m_base;
};

/// URDF's orientation, fixed-axis roll, pitch, yaw (about x, then y, then z of the parent
/// frame): R = Rz(yaw) Ry(pitch) Rx(roll).
Quat quatFromRollPitchYaw(double roll, double pitch, double yaw);

}  // namespace stroma
