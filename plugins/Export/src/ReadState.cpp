// SPDX-License-Identifier: MIT
#include "ReadState.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/Node.h"
#include "simulation/VecId.h"

namespace stroma {

void ReadState::init() {
  m_ready = false;
  m_applied = -1;
  m_hasRead = false;
  m_state = node() ? node()->get<MechanicalState<Vec3Types>>() : nullptr;
  if (!m_state) {
    const auto* other = node() ? node()->get<BaseMechanicalState>() : nullptr;
    msgError(other ? "sets Vec3d states only; " + other->path() + " is " + other->templateName()
                   : std::string("no mechanical state in this node to set"));
    return setInvalid();
  }
  std::string error;
  if (!readSofaStateFile(d_filename.value().path(), m_records, error)) {
    msgError(error, "filename");
    return setInvalid();
  }
  if (m_records.empty()) {
    msgError("state file '" + d_filename.value().path() + "' has no record (no 'T=' line)",
             "filename");
    return setInvalid();
  }
  const std::size_t values = 3 * m_state->size();
  for (const SofaStateRecord& r : m_records) {
    auto check = [&](bool has, const std::vector<double>& v, const char* key) {
      if (!has || v.size() == values) return true;
      msgError("state file '" + d_filename.value().path() + "' record at line " +
                   std::to_string(r.line) + " (T= " + std::to_string(r.time) + "): " + key +
                   "= has " + std::to_string(v.size()) + " numbers, " + m_state->path() +
                   " needs " + std::to_string(values) + " (3 per point)",
               "filename");
      return false;
    };
    if (!check(r.hasPositions, r.positions, "X") || !check(r.hasVelocities, r.velocities, "V"))
      return setInvalid();
  }
  m_ready = true;
}

long long ReadState::recordAt(double t, double tolerance) const {
  const double first = m_records.front().time, last = m_records.back().time;
  if (d_loop.value() && t > last + tolerance && m_records.size() > 1) {
    // One cycle: the records, then one spacing of the last two before the first again.
    const double spacing = last - m_records[m_records.size() - 2].time;
    const double cycle = last - first + spacing;
    if (cycle > 0) t = first + std::fmod(t - first, cycle);
  }
  long long found = -1;
  for (std::size_t k = 0; k < m_records.size() && m_records[k].time <= t + tolerance; ++k)
    found = static_cast<long long>(k);
  return found;
}

void ReadState::stepBegin(double time, double dt) { applyAt(time, dt); }
void ReadState::stepEnd(double time, double dt) { applyAt(time, dt); }

void ReadState::applyAt(double time, double dt) {
  if (!m_ready) return;
  const double interval = d_interval.value();
  if (interval > 0 && m_hasRead && time < m_lastReadTime + interval - 1e-6 * dt) return;
  const long long k = recordAt(time + d_shift.value(), 1e-6 * dt);
  if (k < 0 || k == m_applied) return;
  m_applied = k;
  m_hasRead = true;
  m_lastReadTime = time;
  const SofaStateRecord& r = m_records[static_cast<std::size_t>(k)];
  if (r.hasPositions) {
    const Vec3d a = d_rotation.value() * (std::numbers::pi / 180.0);
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(a.x(), Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    const double scale = d_scalePos.value();
    const Vec3d shift = d_translation.value();
    auto& x = m_state->writeCoord(VecId::position());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3d read(r.positions[3 * i], r.positions[3 * i + 1], r.positions[3 * i + 2]);
      x[i] = R * (scale * read) + shift;
    }
  }
  if (r.hasVelocities) {
    auto& v = m_state->writeDeriv(VecId::velocity());
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = Vec3d(r.velocities[3 * i], r.velocities[3 * i + 1], r.velocities[3 * i + 2]);
  }
}

}  // namespace stroma
