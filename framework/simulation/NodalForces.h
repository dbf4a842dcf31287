// SPDX-License-Identifier: MIT
// The loads that the force fields of a solver's node apply now, as a list of points and forces:
// what solvers that take loads as point forces (the precomputed model's superposition, the
// hybrid model's zones) read at each step instead of a forceIndices/forces pair.
#pragma once

#include <vector>

#include "core/Types.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/MechanicalState.h"

namespace stroma {

struct NodalForces {
  std::vector<int> points;   ///< increasing
  std::vector<Vec3d> forces;  ///< (N), one per point, none zero
};

/// The forces of every force field under `mop` at the current state (computeForce at `dt`),
/// kept on the points of `state` where they are not zero, into `out` (its storage reused: a
/// solver keeping one allocates nothing once warm).
inline void readNodalForces(MechanicalOperations& mop, const MechanicalState<Vec3Types>& state,
                            double dt, NodalForces& out) {
  const VecId f = mop.allocDeriv();
  MechanicalParams mp;
  mp.dt = dt;
  mop.computeForce(mp, f);
  const auto& forces = state.readDeriv(f);
  out.points.clear();
  out.forces.clear();
  for (std::size_t i = 0; i < forces.size(); ++i)
    if (!forces[i].isZero(0)) {
      out.points.push_back(static_cast<int>(i));
      out.forces.push_back(forces[i]);
    }
  mop.freeVec(f);
}

inline NodalForces readNodalForces(MechanicalOperations& mop,
                                   const MechanicalState<Vec3Types>& state, double dt) {
  NodalForces result;
  readNodalForces(mop, state, dt, result);
  return result;
}

}  // namespace stroma
