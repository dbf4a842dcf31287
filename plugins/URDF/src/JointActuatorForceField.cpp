// SPDX-License-Identifier: MIT
#include "JointActuatorForceField.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/Node.h"

namespace stroma {

namespace {
constexpr double kFrictionSpeed = 1e-3;  // v0 of the smoothed Coulomb friction
}

// One value per joint from a Data of nbJoints values, one value, or none (zeros).
bool JointActuatorForceField::perJoint(const Data<std::vector<double>>& data,
                                       std::vector<double>& out) {
  const std::size_t n = mstate()->size();
  const auto& values = data.value();
  if (values.empty()) out.assign(n, 0.0);
  else if (values.size() == 1) out.assign(n, values[0]);
  else if (values.size() == n) out = values;
  else {
    msgError("has " + std::to_string(values.size()) + " values for " + std::to_string(n) +
                 " joint values (give one per joint, or one for all)",
             data.name());
    return false;
  }
  for (double v : out)
    if (!(v >= 0) || !std::isfinite(v)) {
      msgError("values must be finite and non-negative", data.name());
      return false;
    }
  return true;
}

void JointActuatorForceField::init() {
  ForceField<Vec1Types>::init();
  m_ready = false;
  if (!mstate()) return;
  if (!perJoint(d_stiffness, m_stiffness) || !perJoint(d_damping, m_damping) ||
      !perJoint(d_friction, m_friction))
    return;
  const std::size_t n = mstate()->size();
  m_times = d_keyTimes.value();
  m_targets = d_keyTargets.value();
  if (!d_targetFile.value().original.empty() && !readTargetFile()) return;
  if (m_targets.size() != m_times.size() * n) {
    msgError("has " + std::to_string(m_targets.size()) + " values for " +
                 std::to_string(m_times.size()) + " key times x " + std::to_string(n) +
                 " joint values",
             "keyTargets");
    return;
  }
  if (!std::is_sorted(m_times.begin(), m_times.end())) {
    msgError("key times must increase", "keyTimes");
    return;
  }
  d_torques.setValue(std::vector<double>(n, 0.0));
  m_ready = true;
}

bool JointActuatorForceField::readTargetFile() {
  const std::string path = d_targetFile.value().path();
  std::ifstream in(path);
  if (!in) {
    msgError("cannot open '" + path + "'", "targetFile");
    return false;
  }
  const std::size_t n = mstate()->size();
  m_times.clear();
  m_targets.clear();
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    std::vector<double> values;
    double v;
    while (fields >> v) values.push_back(v);
    if (values.empty()) continue;  // a header or a blank line
    if (values.size() != n + 1) {
      msgError("'" + path + "' line " + std::to_string(lineNumber) + ": expected a time and " +
                   std::to_string(n) + " targets, got " + std::to_string(values.size()) +
                   " numbers",
               "targetFile");
      return false;
    }
    m_times.push_back(values[0]);
    m_targets.insert(m_targets.end(), values.begin() + 1, values.end());
  }
  return true;
}

double JointActuatorForceField::target(std::size_t j, double t) const {
  const std::size_t n = mstate()->size();
  if (m_times.empty()) return 0.0;
  if (t <= m_times.front()) return m_targets[j];
  if (t >= m_times.back()) return m_targets[(m_times.size() - 1) * n + j];
  const auto after = std::upper_bound(m_times.begin(), m_times.end(), t);
  const std::size_t k = static_cast<std::size_t>(after - m_times.begin());
  const double s = (t - m_times[k - 1]) / (m_times[k] - m_times[k - 1]);
  return (1 - s) * m_targets[(k - 1) * n + j] + s * m_targets[k * n + j];
}

void JointActuatorForceField::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                       const VecDeriv& v) {
  if (!m_ready) return;
  const double t = node()->time();
  std::vector<double> torques(x.size(), 0.0);
  m_lastVelocity.assign(x.size(), 0.0);
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double qdot = j < v.size() ? v[j][0] : 0.0;
    m_lastVelocity[j] = qdot;
    const double drive = -m_stiffness[j] * (x[j][0] - target(j, t)) - m_damping[j] * qdot;
    torques[j] = drive;
    f[j][0] += drive - m_friction[j] * std::tanh(qdot / kFrictionSpeed);
  }
  d_torques.setValue(torques);
}

void JointActuatorForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                        const VecDeriv& dx) {
  if (!m_ready) return;
  for (std::size_t j = 0; j < df.size(); ++j) {
    const double qdot = j < m_lastVelocity.size() ? m_lastVelocity[j] : 0.0;
    const double sech = 1.0 / std::cosh(qdot / kFrictionSpeed);
    const double b = -m_damping[j] - m_friction[j] * sech * sech / kFrictionSpeed;
    df[j][0] += (mp.kFactor * -m_stiffness[j] + mp.bFactor * b) * dx[j][0];
  }
}

void JointActuatorForceField::addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                           std::size_t offset) {
  if (!m_ready) return;
  for (std::size_t j = 0; j < m_stiffness.size(); ++j) {
    const double qdot = j < m_lastVelocity.size() ? m_lastVelocity[j] : 0.0;
    const double sech = 1.0 / std::cosh(qdot / kFrictionSpeed);
    const double b = -m_damping[j] - m_friction[j] * sech * sech / kFrictionSpeed;
    matrix.add(offset + j, offset + j, mp.kFactor * -m_stiffness[j] + mp.bFactor * b);
  }
}

double JointActuatorForceField::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  if (!m_ready) return 0;
  const double t = node()->time();
  double e = 0;
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double d = x[j][0] - target(j, t);
    e += 0.5 * m_stiffness[j] * d * d;
  }
  return e;
}

}  // namespace stroma
