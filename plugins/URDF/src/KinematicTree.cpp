// SPDX-License-Identifier: MIT
#include "KinematicTree.h"

#include <cmath>

namespace stroma {

bool KinematicTree::setJoints(std::vector<KinematicJoint> joints, std::string& error) {
  m_dofCount = 0;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    KinematicJoint& j = joints[i];
    if (i == 0) {
      j.parent = -1;
      j.type = JointType::fixed;
    } else if (j.parent < 0 || j.parent >= static_cast<int>(i)) {
      error = "link " + std::to_string(i) + " has parent " + std::to_string(j.parent) +
              ", not an earlier link";
      return false;
    }
    if (j.type != JointType::fixed) {
      const double n = j.axis.norm();
      if (!(n > 0) || !std::isfinite(n)) {
        error = "the joint of link " + std::to_string(i) + " has a zero or non-finite axis";
        return false;
      }
      j.axis /= n;
      j.dof = j.mimic < 0 ? static_cast<int>(m_dofCount++) : -1;
    } else {
      j.dof = -1;
      j.mimic = -1;
    }
    if (j.mimic < 0) {
      j.multiplier = 1;
      j.offset = 0;
    }
    j.origin.orientation.normalize();
  }
  // A mimic joint takes its source's value number (the source may come later in the tree).
  for (std::size_t i = 0; i < joints.size(); ++i) {
    KinematicJoint& j = joints[i];
    if (j.mimic < 0) continue;
    const bool valid = j.mimic < static_cast<int>(joints.size()) &&
                       joints[static_cast<std::size_t>(j.mimic)].mimic < 0 &&
                       joints[static_cast<std::size_t>(j.mimic)].dof >= 0;
    if (!valid || !std::isfinite(j.multiplier) || !std::isfinite(j.offset)) {
      error = "the joint of link " + std::to_string(i) + " mimics link " +
              std::to_string(j.mimic) + ", whose joint is not an independent moving one";
      return false;
    }
    j.dof = joints[static_cast<std::size_t>(j.mimic)].dof;
  }
  m_joints = std::move(joints);
  return true;
}

void KinematicTree::computeFrames(const std::vector<Vec1d>& q,
                                  std::vector<RigidCoord3>& frames) const {
  frames.resize(m_joints.size());
  for (std::size_t i = 0; i < m_joints.size(); ++i) {
    const KinematicJoint& j = m_joints[i];
    const RigidCoord3& parent = j.parent < 0 ? m_base : frames[j.parent];
    // The joint frame in the world, then the joint's motion in it.
    Vec3d center = parent.center + parent.orientation * j.origin.center;
    Quat orientation = parent.orientation * j.origin.orientation;
    const double value = j.dof >= 0 && static_cast<std::size_t>(j.dof) < q.size()
                             ? j.multiplier * q[j.dof][0] + j.offset
                             : 0.0;
    if (j.type == JointType::revolute)
      orientation = orientation * Quat(Eigen::AngleAxisd(value, j.axis));
    else if (j.type == JointType::prismatic)
      center += orientation * (value * j.axis);
    frames[i] = {center, orientation.normalized()};
  }
}

void KinematicTree::computePointJacobian(const std::vector<RigidCoord3>& frames, int link,
                                         const Vec3d& point,
                                         std::vector<RigidDeriv3>& columns) const {
  columns.assign(m_dofCount, RigidDeriv3{});
  forEachMovingJointOnChain(link, [&](int i) {
    const KinematicJoint& j = m_joints[i];
    // The joint's axis in the world is the same before and after its own motion (a rotation
    // about it, or a translation along it); it is the child link's orientation times axis.
    const Vec3d axis = frames[i].orientation * j.axis;
    RigidDeriv3& c = columns[j.dof];
    if (j.type == JointType::revolute) {
      // The joint frame's origin is on the axis: the child link's center for a revolute joint.
      c.linear += j.multiplier * axis.cross(point - frames[i].center);
      c.angular += j.multiplier * axis;
    } else {
      c.linear += j.multiplier * axis;
    }
  });
}

Quat quatFromRollPitchYaw(double roll, double pitch, double yaw) {
  return Quat(Eigen::AngleAxisd(yaw, Vec3d::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3d::UnitY()) *
              Eigen::AngleAxisd(roll, Vec3d::UnitX()));
}

}  // namespace stroma
