// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "SofaStateFile.h"
#include "core/Base.h"
#include "core/Data.h"
#include "core/StateTypes.h"
#include "core/Types.h"
#include "simulation/MechanicalState.h"
#include "simulation/StepListener.h"

namespace stroma {

/// SOFA's ReadState: sets the positions (X=) and velocities (V=) of its node's mechanical state
/// (Vec3d) from a state file in SOFA's format (SofaStateFile.h; ".gz" read through zlib), as
/// SOFA's WriteState or Stroma's writes it. At each step's begin and end, at scene time t, the
/// last record whose time is <= t + shift (to a millionth of a step) is applied, once: a scene
/// that replays the file shows after each step the record of the step's end time. Positions
/// read are scaled by scalePos, rotated by `rotation` (degrees about x, then y, then z), then
/// translated. `interval` > 0 reads only when that much time passed since the last read;
/// `loop` starts the file again after its last record (the next cycle begins one record
/// spacing after it).
///
/// Errors at init, with the file's line: a missing or malformed file, a record whose X= or V=
/// count is not the state's number of values.
class ReadState final : public Base, public StepListener {
 public:
  Data<FileName> d_filename{this, "filename", {}, "State file to read (SOFA's WriteState format)."};
  Data<double> d_interval{this,
                          "interval",
                          0.0,
                          "Time between two reads; 0: at every step.",
                          {.unit = "s", .min = 0.0}};
  Data<double> d_shift{this,
                       "shift",
                       0.0,
                       "Added to the scene time to get the time looked up in the file.",
                       {.unit = "s"}};
  Data<bool> d_loop{this, "loop", false, "Start the file again after its last record."};
  Data<double> d_scalePos{this, "scalePos", 1.0, "Factor applied to the positions read."};
  Data<Vec3d> d_rotation{this,
                         "rotation",
                         Vec3d::Zero(),
                         "Rotation of the positions read: angles about x, y then z.",
                         {.unit = "deg"}};
  Data<Vec3d> d_translation{this,
                            "translation",
                            Vec3d::Zero(),
                            "Translation added to the positions read (after scale and "
                            "rotation).",
                            {.unit = "m"}};

  void init() override;
  void stepBegin(double time, double dt) override;
  void stepEnd(double time, double dt) override;

  /// The records read from the file.
  const std::vector<SofaStateRecord>& records() const { return m_records; }

 private:
  void applyAt(double time, double dt);
  /// The record to apply at file time t, or -1 before the first.
  long long recordAt(double t, double tolerance) const;

  MechanicalState<Vec3Types>* m_state = nullptr;
  std::vector<SofaStateRecord> m_records;
  long long m_applied = -1;
  double m_lastReadTime = 0;
  bool m_hasRead = false;
  bool m_ready = false;
};

}  // namespace stroma
