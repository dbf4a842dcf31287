// SPDX-License-Identifier: MIT
#include "WriteState.h"

#include <cmath>

#include "OutputFile.h"
#include "core/Node.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/VecId.h"

namespace stroma {

void WriteState::init() {
  m_ready = false;
  m_nextIndex = 0;
  m_records = 0;
  m_state = node() ? node()->get<BaseMechanicalState>() : nullptr;
  if (!m_state) {
    msgError("no mechanical state in this node to write");
    return setInvalid();
  }
  const std::vector<double>& times = d_time.value();
  for (std::size_t k = 1; k < times.size(); ++k)
    if (times[k] < times[k - 1]) {
      msgError("times must increase (" + std::to_string(times[k - 1]) + " then " +
                   std::to_string(times[k]) + ")",
               "time");
      return setInvalid();
    }
  for (const auto* field : {&d_DOFsX, &d_DOFsV})
    for (unsigned i : field->value())
      if (i >= m_state->size()) {
        msgError("degree of freedom " + std::to_string(i) + " out of the " +
                     std::to_string(m_state->size()) + " of " + m_state->path(),
                 field->name());
        return setInvalid();
      }
  if ((d_writeX0.value() || d_writeF.value()) &&
      !dynamic_cast<MechanicalState<Vec3Types>*>(m_state)) {
    msgError("writeX0 and writeF need a Vec3d state; " + m_state->path() + " is " +
             m_state->templateName());
    return setInvalid();
  }
  const std::string file = d_filename.value().original;
  if (!checkOutputFolder(*this, file, "filename")) return setInvalid();
  std::string error;
  if (!m_writer.open(file, error)) {
    msgError(error, "filename");
    return setInvalid();
  }
  m_ready = true;
}

bool WriteState::scheduledTime(std::size_t index, double& time) const {
  const std::vector<double>& times = d_time.value();
  if (index < times.size()) {
    time = times[index];
    return true;
  }
  const double period = d_period.value();
  if (period <= 0) return false;
  const double last = times.empty() ? 0.0 : times.back();
  time = last + period * static_cast<double>(index - times.size() + (times.empty() ? 0 : 1));
  return true;
}

void WriteState::stepBegin(double time, double dt) {
  // The initial state, before the first step (later begins equal the previous ends).
  if (m_ready && m_records == 0 && m_nextIndex == 0) writeIfDue(time, dt);
}

void WriteState::stepEnd(double time, double dt) {
  if (m_ready) writeIfDue(time, dt);
}

void WriteState::writeIfDue(double time, double dt) {
  double next = 0;
  if (!scheduledTime(m_nextIndex, next) || time < next - 0.5 * dt) return;
  if (!writeRecord(time)) return;
  // Skip the scheduled times this record covers (a period shorter than the step).
  while (scheduledTime(m_nextIndex, next) && next <= time + 0.5 * dt) ++m_nextIndex;
}

bool WriteState::writeRecord(double time) {
  SofaStateRecord r;
  r.time = time;
  auto select = [](const std::vector<double>& all, int dimension,
                   const std::vector<unsigned>& dofs) {
    if (dofs.empty()) return all;
    std::vector<double> chosen;
    for (unsigned i : dofs)
      for (int a = 0; a < dimension; ++a) chosen.push_back(all[i * dimension + a]);
    return chosen;
  };
  const int dx = m_state->coordDimension(), dv = m_state->derivDimension();
  std::vector<double> values;
  if (d_writeX.value()) {
    m_state->copyPositions(values);
    r.positions = select(values, dx, d_DOFsX.value());
    r.hasPositions = true;
  }
  auto* vec3 = dynamic_cast<MechanicalState<Vec3Types>*>(m_state);
  auto flatten = [](const std::vector<Vec3d>& v) {
    std::vector<double> flat;
    for (const Vec3d& p : v) flat.insert(flat.end(), {p.x(), p.y(), p.z()});
    return flat;
  };
  if (d_writeX0.value() && vec3) {
    r.restPositions = select(flatten(vec3->readCoord(VecId::restPosition())), 3, d_DOFsX.value());
    r.hasRestPositions = true;
  }
  if (d_writeV.value()) {
    m_state->copyVelocities(values);
    r.velocities = select(values, dv, d_DOFsV.value());
    r.hasVelocities = true;
  }
  if (d_writeF.value() && vec3) {
    r.forces = select(flatten(vec3->readDeriv(VecId::force())), 3, d_DOFsV.value());
    r.hasForces = true;
  }
  std::string error;
  if (!m_writer.write(r, error)) {
    msgError(error, "filename");
    m_ready = false;
    return false;
  }
  ++m_records;
  return true;
}

void WriteState::cleanup() {
  std::string error;
  if (!m_writer.close(error)) msgError(error, "filename");
  m_ready = false;
}

}  // namespace stroma
