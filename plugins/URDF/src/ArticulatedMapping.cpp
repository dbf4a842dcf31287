// SPDX-License-Identifier: MIT
#include "ArticulatedMapping.h"

#include "../../Mapping/src/MappedOutput.h"

namespace stroma {

bool jointTypeFromName(const std::string& name, JointType& type) {
  if (name == "fixed") type = JointType::fixed;
  else if (name == "revolute" || name == "continuous") type = JointType::revolute;
  else if (name == "prismatic") type = JointType::prismatic;
  else return false;
  return true;
}

void ArticulatedMapping::init() {
  m_ready = false;
  if (!findStates()) return;
  if (!setUp()) return;
  m_ready = true;
  if (!output()) return;
  const std::size_t n = m_outputLinks.size();
  resizeOutput(*output(), n);
  if (input()->size() != m_tree.dofCount()) {
    msgError("the input has " + std::to_string(input()->size()) + " values for " +
                 std::to_string(m_tree.dofCount()) + " moving joints",
             "input");
    m_ready = false;
    return;
  }
  // The output's rest frames are those of the input's rest values.
  applyAtInit(*this, true);
}

// The kinematic tree from the Data; false after an error naming the field.
bool ArticulatedMapping::setUp() {
  const std::size_t links = d_parents.value().size();
  auto sized = [&](std::size_t count, const BaseData& data) {
    if (count == links || count == 0) return true;
    msgError("has " + std::to_string(count) + " entries for " + std::to_string(links) +
                 " links (parents)",
             data.name());
    return false;
  };
  if (links == 0) {
    msgError("no link: give each link's parent", "parents");
    return false;
  }
  if (!sized(d_jointTypes.value().size(), d_jointTypes) ||
      !sized(d_origins.value().size(), d_origins) || !sized(d_axes.value().size(), d_axes) ||
      !sized(d_mimic.value().size(), d_mimic) ||
      !sized(d_mimicMultipliers.value().size(), d_mimicMultipliers) ||
      !sized(d_mimicOffsets.value().size(), d_mimicOffsets))
    return false;
  std::vector<KinematicJoint> joints(links);
  for (std::size_t i = 0; i < links; ++i) {
    KinematicJoint& j = joints[i];
    j.parent = d_parents.value()[i];
    if (!d_origins.value().empty()) j.origin = d_origins.value()[i];
    if (!d_axes.value().empty()) j.axis = d_axes.value()[i];
    if (!d_mimic.value().empty()) j.mimic = d_mimic.value()[i];
    if (!d_mimicMultipliers.value().empty()) j.multiplier = d_mimicMultipliers.value()[i];
    if (!d_mimicOffsets.value().empty()) j.offset = d_mimicOffsets.value()[i];
    if (!d_jointTypes.value().empty() && !jointTypeFromName(d_jointTypes.value()[i], j.type)) {
      msgError("unknown joint type '" + d_jointTypes.value()[i] + "' of link " +
                   std::to_string(i) + " (fixed, revolute, continuous or prismatic)",
               "jointTypes");
      return false;
    }
  }
  if (joints[0].type != JointType::fixed || joints[0].parent != -1) {
    msgError("the first link is the base: its parent is -1 and its joint fixed", "parents");
    return false;
  }
  std::string why;
  if (!m_tree.setJoints(std::move(joints), why)) {
    msgError(why, why.find("mimics") != std::string::npos ? "mimic" : "parents");
    return false;
  }
  m_tree.setBase(d_base.value());

  m_outputLinks = d_outputLinks.value();
  if (m_outputLinks.empty())
    for (unsigned i = 0; i < links; ++i) m_outputLinks.push_back(i);
  for (unsigned k : m_outputLinks)
    if (k >= links) {
      msgError("link " + std::to_string(k) + " is out of range of the " +
                   std::to_string(links) + " links",
               "outputLinks");
      return false;
    }
  m_outputOffsets = d_outputOffsets.value();
  if (m_outputOffsets.empty()) m_outputOffsets.assign(m_outputLinks.size(), RigidCoord3{});
  if (m_outputOffsets.size() != m_outputLinks.size()) {
    msgError("has " + std::to_string(m_outputOffsets.size()) + " frames for " +
                 std::to_string(m_outputLinks.size()) + " output frames",
             "outputOffsets");
    return false;
  }
  return true;
}

void ArticulatedMapping::apply(OutVecCoord& out, const InVecCoord& in) {
  if (!m_ready) return;
  m_tree.computeFrames(in, m_linkFrames);
  out.resize(m_outputLinks.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const RigidCoord3& link = m_linkFrames[m_outputLinks[k]];
    const RigidCoord3& offset = m_outputOffsets[k];
    out[k].center = link.center + link.orientation * offset.center;
    out[k].orientation = (link.orientation * offset.orientation).normalized();
  }
}

void ArticulatedMapping::computeJacobian(const InVecCoord& q) {
  const std::size_t n = m_outputLinks.size();
  m_tree.computeFrames(q, m_linkFrames);
  m_triplets.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const RigidCoord3& link = m_linkFrames[m_outputLinks[k]];
    const Vec3d center = link.center + link.orientation * m_outputOffsets[k].center;
    m_tree.computePointJacobian(m_linkFrames, static_cast<int>(m_outputLinks[k]), center,
                                m_columns);
    // Each value's column once (a mimic joint on the chain adds to its source's column).
    for (std::size_t dof = 0; dof < m_columns.size(); ++dof) {
      const RigidDeriv3& c = m_columns[dof];
      for (int r = 0; r < 3; ++r) {
        if (c.linear[r] != 0) m_triplets.emplace_back(6 * k + r, static_cast<int>(dof), c.linear[r]);
        if (c.angular[r] != 0)
          m_triplets.emplace_back(6 * k + 3 + r, static_cast<int>(dof), c.angular[r]);
      }
    }
  }
  m_J.resize(static_cast<Eigen::Index>(6 * n), static_cast<Eigen::Index>(m_tree.dofCount()));
  m_J.setFromTriplets(m_triplets.begin(), m_triplets.end());
}

void ArticulatedMapping::applyJ(OutVecDeriv& out, const InVecDeriv& in) {
  if (!m_ready) return;
  computeJacobian(input()->readCoord(VecId::position()));
  Eigen::VectorXd qdot(in.size());
  for (std::size_t j = 0; j < in.size(); ++j) qdot[j] = in[j][0];
  const Eigen::VectorXd v = m_J * qdot;
  out.resize(m_outputLinks.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].linear = v.segment<3>(6 * k);
    out[k].angular = v.segment<3>(6 * k + 3);
  }
}

void ArticulatedMapping::applyJT(InVecDeriv& in, const OutVecDeriv& out) {
  if (!m_ready) return;
  computeJacobian(input()->readCoord(VecId::position()));
  Eigen::VectorXd f(6 * out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    f.segment<3>(6 * k) = out[k].linear;
    f.segment<3>(6 * k + 3) = out[k].angular;
  }
  const Eigen::VectorXd tau = m_J.transpose() * f;
  in.resize(m_tree.dofCount(), Vec1d::Zero());
  for (std::size_t j = 0; j < in.size(); ++j) in[j][0] += tau[j];
}

const Eigen::SparseMatrix<double>& ArticulatedMapping::jacobian() {
  if (m_ready) computeJacobian(input()->readCoord(VecId::position()));
  return m_J;
}

}  // namespace stroma
