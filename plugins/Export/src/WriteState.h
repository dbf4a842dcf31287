// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "SofaStateFile.h"
#include "core/Base.h"
#include "core/Data.h"
#include "core/Types.h"
#include "simulation/StepListener.h"

namespace stroma {

class BaseMechanicalState;

/// SOFA's WriteState: writes the state of its node's mechanical state to a text file in SOFA's
/// format (SofaStateFile.h: "T= t" then "  X= ...", "  X0= ...", "  V= ...", "  F= ..." lines),
/// at the times of `time`, then every `period` after the last of them. With the defaults
/// (time 0, period 0) it writes the initial state only, as SOFA's. A record at time t holds
/// the state at t: the initial state before the first step, then the state after each step
/// whose end reaches the next time (within half a step). DOFsX and DOFsV restrict the written
/// degrees of freedom. A name ending in ".gz" is gzip-compressed.
class WriteState final : public Base, public StepListener {
 public:
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "Output file (\".gz\": compressed); relative to the working folder.",
                            {.output = true}};
  Data<bool> d_writeX{this, "writeX", true, "Write the positions (X=)."};
  Data<bool> d_writeX0{this, "writeX0", false, "Write the rest positions (X0=)."};
  Data<bool> d_writeV{this, "writeV", false, "Write the velocities (V=)."};
  Data<bool> d_writeF{this, "writeF", false, "Write the forces (F=)."};
  Data<std::vector<double>> d_time{this,
                                   "time",
                                   {0.0},
                                   "Times to write at (increasing), before `period` applies.",
                                   {.unit = "s", .min = 0.0}};
  Data<double> d_period{this,
                        "period",
                        0.0,
                        "Time between records after the last of `time`; 0: none.",
                        {.unit = "s", .min = 0.0}};
  Data<std::vector<unsigned>> d_DOFsX{this,
                                      "DOFsX",
                                      {},
                                      "Degrees of freedom whose positions are written; empty: "
                                      "all."};
  Data<std::vector<unsigned>> d_DOFsV{this,
                                      "DOFsV",
                                      {},
                                      "Degrees of freedom whose velocities (and forces) are "
                                      "written; empty: all."};

  void init() override;
  void cleanup() override;
  void stepBegin(double time, double dt) override;
  void stepEnd(double time, double dt) override;

  /// Records written so far.
  std::size_t recordCount() const { return m_records; }

 private:
  void writeIfDue(double time, double dt);
  bool writeRecord(double time);
  /// The time after `m_nextIndex` scheduled times (the list, then every period); false when
  /// nothing more is scheduled.
  bool scheduledTime(std::size_t index, double& time) const;

  BaseMechanicalState* m_state = nullptr;
  SofaStateWriter m_writer;
  std::size_t m_nextIndex = 0;
  std::size_t m_records = 0;
  bool m_ready = false;
};

}  // namespace stroma
