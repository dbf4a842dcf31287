// SPDX-License-Identifier: MIT
// When an exporter writes (SOFA's exportEveryNumberOfSteps, exportAtBegin, exportAtEnd,
// enable): Data registered on the exporter, as members, and the step count. The exporters
// write at the end of a step (StepListener::stepEnd), at bwdInit for exportAtBegin (every state
// and mapping is initialized then) and at cleanup for exportAtEnd.
#pragma once

#include <string>

#include "core/Base.h"
#include "core/Data.h"

namespace stroma {

class ExportSchedule {
 public:
  explicit ExportSchedule(Base& owner) : m_owner(owner) {}

 private:
  Base& m_owner;  // first: the Data below register with it

 public:
  Data<int> d_exportEveryNumberOfSteps{
      &m_owner,
      "exportEveryNumberOfSteps",
      0,
      "Write after every N steps (steps N, 2N, ...); 0: never during the run.",
      {.min = 0.0}};
  Data<bool> d_exportAtBegin{&m_owner, "exportAtBegin", false,
                             "Write once before the first step (after initialization)."};
  Data<bool> d_exportAtEnd{&m_owner, "exportAtEnd", false,
                           "Write once when the scene is closed (the end of the run)."};
  Data<bool> d_enable{&m_owner, "enable", true, "Write nothing when false."};

  /// Counts a finished step; true when it is one to write after.
  bool stepDone() {
    ++m_steps;
    const int every = d_exportEveryNumberOfSteps.value();
    return d_enable.value() && every > 0 && m_steps % every == 0;
  }
  bool atBegin() const { return d_enable.value() && d_exportAtBegin.value(); }
  bool atEnd() const { return d_enable.value() && d_exportAtEnd.value(); }
  /// Steps done since the scene was loaded.
  long long steps() const { return m_steps; }
  /// What follows the file name of the next file, as SOFA's exporters number them: the export's
  /// number from 1 on 5 digits ("00001") when exportEveryNumberOfSteps > 0, else nothing (one
  /// file, rewritten by a later export).
  std::string nextFileSuffix() {
    if (d_exportEveryNumberOfSteps.value() <= 0) return {};
    const std::string number = std::to_string(++m_exports);
    return std::string(number.size() < 5 ? 5 - number.size() : 0, '0') + number;
  }

 private:
  long long m_steps = 0;
  long long m_exports = 0;
};

}  // namespace stroma
