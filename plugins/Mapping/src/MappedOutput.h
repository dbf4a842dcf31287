// SPDX-License-Identifier: MIT
// What every mapping of this plugin does with its output at init: SOFA's mapping options
// (accepted, and reported when they ask for something Stroma does not do), giving the output
// the number of points the mapping defines, and a first apply so that the output starts where
// the mapping puts it.
#pragma once

#include <string>

#include "core/Base.h"
#include "simulation/Mapping.h"
#include "simulation/VecId.h"

namespace stroma {

/// SOFA's BaseMapping options, as Data of the mapping that holds this struct.
struct SofaMappingOptions {
  explicit SofaMappingOptions(Base* owner)
      : isMechanical{owner, "isMechanical", true,
                     "SOFA option: false for a mapping that only moves its output (SOFA updates "
                     "it after the step). Stroma maps a state output mechanically; a visual "
                     "output is never mapped in batch runs."},
        mapForces{owner, "mapForces", true,
                  "SOFA option: forces of the output go to the input through J^T. Stroma "
                  "always does it for a state output."},
        mapMasses{owner, "mapMasses", true,
                  "SOFA option: masses of the output go to the input (J^T M J). Stroma always "
                  "does it for a state output."},
        mapConstraints{owner, "mapConstraints", true,
                       "SOFA option for Lagrangian constraints, accepted."},
        applyRestPosition{owner, "applyRestPosition", false,
                          "Also map the input's rest positions to the output's at init."} {}

  Data<bool> isMechanical;
  Data<bool> mapForces;
  Data<bool> mapMasses;
  Data<bool> mapConstraints;
  Data<bool> applyRestPosition;

  /// Warns when an option asks to leave out forces or masses of a mechanical output, which
  /// Stroma does not do (the output then counts as mechanical).
  void warnUnsupported(const Base& mapping, bool mechanicalOutput) const {
    if (!mechanicalOutput) return;
    for (const Data<bool>* d : {&isMechanical, &mapForces, &mapMasses})
      if (!d->value())
        mapping.msgWarning(d->name() +
                               "=false is not supported for a state output: its forces "
                               "and masses are mapped to the input",
                           d->name());
  }
};

/// Makes the output hold `n` points when it holds another number (SOFA's mappings size their
/// output): every coordinate vector is resized; velocities and forces follow the positions.
/// Returns true when the size changed.
template <class Out>
bool resizeOutput(MechanicalState<Out>& out, std::size_t n) {
  if (out.size() == n) return false;
  for (VecId v :
       {VecId::position(), VecId::restPosition(), VecId::freePosition(), VecId::resetPosition()})
    out.writeCoord(v).resize(n, Out::zeroCoord());
  return true;
}

/// The first apply of SOFA's Mapping::init: positions (and free positions) and velocities of
/// the output from the input's; rest positions too when asked or when the output was just
/// sized by the mapping (it had no rest shape of its own).
template <class In, class Out>
void applyAtInit(Mapping<In, Out>& mapping, bool restPositionsToo) {
  MechanicalState<Out>* out = mapping.output();
  if (!out) return;
  mapping.applyPositions(VecId::position(), VecId::position());
  mapping.applyVelocities(VecId::velocity(), VecId::velocity());
  out->writeCoord(VecId::freePosition()) = out->readCoord(VecId::position());
  if (restPositionsToo) {
    mapping.applyPositions(VecId::restPosition(), VecId::restPosition());
    out->writeCoord(VecId::resetPosition()) = out->readCoord(VecId::position());
  }
}

}  // namespace stroma
