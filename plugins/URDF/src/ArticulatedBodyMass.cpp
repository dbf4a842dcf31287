// SPDX-License-Identifier: MIT
#include "ArticulatedBodyMass.h"

#include <cmath>

#include "core/Node.h"

namespace stroma {

namespace {

constexpr double kStep = 1e-6;  // central differences in q

Eigen::VectorXd toVector(const std::vector<Vec1d>& v) {
  Eigen::VectorXd out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i][0];
  return out;
}

std::vector<Vec1d> shifted(const std::vector<Vec1d>& q, std::size_t j, double step) {
  std::vector<Vec1d> out = q;
  out[j][0] += step;
  return out;
}

}  // namespace

void ArticulatedBodyMass::init() {
  Mass<Vec1Types>::init();
  m_cachedQ.clear();
  if (!l_mapping) {
    msgError("no ArticulatedMapping: link it (mapping=\"@path\")", "mapping");
    return;
  }
  const std::size_t links = l_mapping->d_parents.value().size();
  const auto& masses = d_linkMasses.value();
  if (masses.size() != links) {
    msgError("has " + std::to_string(masses.size()) + " masses for " + std::to_string(links) +
                 " links",
             "linkMasses");
    return;
  }
  for (std::size_t i = 0; i < links; ++i)
    if (!(masses[i] >= 0) || !std::isfinite(masses[i])) {
      msgError("the mass of link " + std::to_string(i) + " is " + std::to_string(masses[i]) +
                   ": it must be finite and non-negative",
               "linkMasses");
      return;
    }
  if (!d_centersOfMass.value().empty() && d_centersOfMass.value().size() != links) {
    msgError("has " + std::to_string(d_centersOfMass.value().size()) + " centers for " +
                 std::to_string(links) + " links",
             "centersOfMass");
    return;
  }
  const auto& armature = d_armature.value();
  const std::size_t joints = mstate() ? mstate()->size() : 0;
  if (armature.size() > 1 && armature.size() != joints) {
    msgError("has " + std::to_string(armature.size()) + " values for " +
                 std::to_string(joints) + " joint values (give one per joint, or one for all)",
             "armature");
    return;
  }
  for (double a : armature)
    if (!(a >= 0) || !std::isfinite(a)) {
      msgError("values must be finite and non-negative", "armature");
      return;
    }
  const auto& values = d_inertias.value();
  if (!values.empty() && values.size() != 6 * links) {
    msgError("has " + std::to_string(values.size()) + " values for " + std::to_string(links) +
                 " links (6 per link: ixx ixy ixz iyy iyz izz)",
             "inertias");
    return;
  }
  m_inertias.assign(links, Mat3d::Zero());
  for (std::size_t i = 0; i < links && !values.empty(); ++i) {
    const double* c = &values[6 * i];
    Mat3d I;
    I << c[0], c[1], c[2], c[1], c[3], c[4], c[2], c[4], c[5];
    // A body's inertia is positive semi-definite (zero for a link without mass or a point).
    const double smallest = Eigen::SelfAdjointEigenSolver<Mat3d>(I).eigenvalues().minCoeff();
    if (!I.allFinite() || smallest < -1e-12 * std::max(1.0, I.norm())) {
      msgError("the inertia of link " + std::to_string(i) +
                   " is not positive semi-definite (smallest eigenvalue " +
                   std::to_string(smallest) + " kg m^2)",
               "inertias");
      return;
    }
    m_inertias[i] = I;
  }
}

bool ArticulatedBodyMass::ready() const {
  return l_mapping && mstate() && m_inertias.size() == l_mapping->tree().linkCount() &&
         l_mapping->tree().dofCount() == mstate()->size() && mstate()->size() > 0;
}

Eigen::MatrixXd ArticulatedBodyMass::computeMassMatrix(const VecCoord& q) const {
  const KinematicTree& tree = l_mapping->tree();
  const std::size_t n = tree.dofCount();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  std::vector<RigidCoord3> frames;
  tree.computeFrames(q, frames);
  std::vector<RigidDeriv3> columns;
  Eigen::MatrixXd Jv(3, n), Jw(3, n);
  for (std::size_t i = 0; i < tree.linkCount(); ++i) {
    const double m = d_linkMasses.value()[i];
    if (m == 0 && m_inertias[i].isZero()) continue;
    const Vec3d com = d_centersOfMass.value().empty() ? Vec3d::Zero() : d_centersOfMass.value()[i];
    const Mat3d R = frames[i].orientation.toRotationMatrix();
    tree.computePointJacobian(frames, static_cast<int>(i), frames[i].center + R * com, columns);
    for (std::size_t j = 0; j < n; ++j) {
      Jv.col(j) = columns[j].linear;
      Jw.col(j) = columns[j].angular;
    }
    M += m * Jv.transpose() * Jv + Jw.transpose() * (R * m_inertias[i] * R.transpose()) * Jw;
  }
  const auto& armature = d_armature.value();
  for (std::size_t j = 0; j < n; ++j)
    M(j, j) += armature.empty() ? 0.0 : armature.size() == 1 ? armature[0] : armature[j];
  return M;
}

Eigen::VectorXd ArticulatedBodyMass::computeGravityForce(const VecCoord& q) const {
  const KinematicTree& tree = l_mapping->tree();
  const Vec3d g = node()->gravity();
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(tree.dofCount());
  std::vector<RigidCoord3> frames;
  tree.computeFrames(q, frames);
  std::vector<RigidDeriv3> columns;
  for (std::size_t i = 0; i < tree.linkCount(); ++i) {
    const double m = d_linkMasses.value()[i];
    if (m == 0) continue;
    const Vec3d com = d_centersOfMass.value().empty() ? Vec3d::Zero() : d_centersOfMass.value()[i];
    tree.computePointJacobian(frames, static_cast<int>(i),
                              frames[i].center + frames[i].orientation * com, columns);
    for (std::size_t j = 0; j < columns.size(); ++j) tau[j] += m * columns[j].linear.dot(g);
  }
  return tau;
}

Eigen::VectorXd ArticulatedBodyMass::computeVelocityForce(const VecCoord& q,
                                                          const VecDeriv& qdot) const {
  const std::size_t n = q.size();
  const Eigen::VectorXd v = toVector(qdot);
  Eigen::VectorXd mdotV = Eigen::VectorXd::Zero(n);  // dM/dt qdot
  Eigen::VectorXd halfGradient(n);                   // 1/2 d(qdot^T M qdot)/dq
  for (std::size_t j = 0; j < n; ++j) {
    const Eigen::MatrixXd dM = (computeMassMatrix(shifted(q, j, kStep)) -
                                computeMassMatrix(shifted(q, j, -kStep))) /
                               (2 * kStep);
    mdotV += v[j] * (dM * v);
    halfGradient[j] = 0.5 * v.dot(dM * v);
  }
  return halfGradient - mdotV;
}

Eigen::MatrixXd ArticulatedBodyMass::computeGravityStiffness(const VecCoord& q) const {
  const std::size_t n = q.size();
  Eigen::MatrixXd K(n, n);
  for (std::size_t j = 0; j < n; ++j)
    K.col(j) = (computeGravityForce(shifted(q, j, kStep)) -
                computeGravityForce(shifted(q, j, -kStep))) /
               (2 * kStep);
  return 0.5 * (K + K.transpose());  // the Hessian of the potential: symmetric
}

const Eigen::MatrixXd& ArticulatedBodyMass::massAtCurrentPosition() const {
  const VecCoord& q = mstate()->readCoord(VecId::position());
  if (q != m_cachedQ || m_cachedM.rows() != static_cast<Eigen::Index>(q.size())) {
    m_cachedM = computeMassMatrix(q);
    m_cachedQ = q;
  }
  return m_cachedM;
}

void ArticulatedBodyMass::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                   const VecDeriv& v) {
  if (!ready()) return;
  Eigen::VectorXd tau = computeGravityForce(x);
  if (v.size() == x.size()) tau += computeVelocityForce(x, v);
  for (std::size_t j = 0; j < f.size() && j < x.size(); ++j) f[j][0] += tau[j];
}

void ArticulatedBodyMass::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                    const VecDeriv& dx) {
  if (!ready() || mp.kFactor == 0) return;
  const Eigen::VectorXd out =
      mp.kFactor * (computeGravityStiffness(mstate()->readCoord(mp.x)) * toVector(dx));
  for (std::size_t j = 0; j < df.size(); ++j) df[j][0] += out[j];
}

void ArticulatedBodyMass::addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                       std::size_t offset) {
  if (!ready() || mp.kFactor == 0) return;
  const Eigen::MatrixXd K = computeGravityStiffness(mstate()->readCoord(mp.x));
  for (Eigen::Index r = 0; r < K.rows(); ++r)
    for (Eigen::Index c = 0; c < K.cols(); ++c)
      matrix.add(offset + r, offset + c, mp.kFactor * K(r, c));
}

double ArticulatedBodyMass::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  if (!ready()) return 0;
  const KinematicTree& tree = l_mapping->tree();
  std::vector<RigidCoord3> frames;
  tree.computeFrames(x, frames);
  const Vec3d g = node()->gravity();
  double e = 0;
  for (std::size_t i = 0; i < tree.linkCount(); ++i) {
    const Vec3d com = d_centersOfMass.value().empty() ? Vec3d::Zero() : d_centersOfMass.value()[i];
    e -= d_linkMasses.value()[i] * g.dot(frames[i].center + frames[i].orientation * com);
  }
  return e;
}

void ArticulatedBodyMass::addMDx(VecDeriv& f, const VecDeriv& dx, double factor) {
  if (!ready()) return;
  const Eigen::VectorXd out = factor * (massAtCurrentPosition() * toVector(dx));
  for (std::size_t j = 0; j < f.size(); ++j) f[j][0] += out[j];
}

void ArticulatedBodyMass::accFromF(VecDeriv& a, const VecDeriv& f) {
  if (!ready()) return;
  const Eigen::VectorXd out = massAtCurrentPosition().ldlt().solve(toVector(f));
  a.resize(f.size());
  for (std::size_t j = 0; j < a.size(); ++j) a[j][0] = out[j];
}

void ArticulatedBodyMass::addMToMatrix(MatrixAccumulator& matrix, std::size_t offset,
                                       double factor) {
  if (!ready()) return;
  const Eigen::MatrixXd& M = massAtCurrentPosition();
  for (Eigen::Index r = 0; r < M.rows(); ++r)
    for (Eigen::Index c = 0; c < M.cols(); ++c)
      matrix.add(offset + r, offset + c, factor * M(r, c));
}

double ArticulatedBodyMass::kineticEnergy(const VecDeriv& v) const {
  if (!ready()) return 0;
  const Eigen::VectorXd qdot = toVector(v);
  return 0.5 * qdot.dot(massAtCurrentPosition() * qdot);
}

}  // namespace stroma
